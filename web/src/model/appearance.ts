// Hopsan GUI layout facts per component type (display name, library folder, icon size, ports
// as fractions of the icon with their angle), from the committed extract of appearance.json.
import extract from './appearance.generated.json';

export interface TypeAppearance {
    displayName: string;
    /** Palette folder path, e.g. "Hydraulic/Valves/DirectionalValves". */
    library: string;
    width: number;
    height: number;
    /** Port name -> [x, y, angle]: x and y as fractions of the icon's width and height. */
    ports: Record<string, [number, number, number]>;
    /** True when Hopsan keeps the graphic upright (iconRotation not ON): only box and ports turn. */
    upright?: true;
}

const types = (extract as unknown as { types: Record<string, TypeAppearance> }).types;

export function appearanceOf(type: string): TypeAppearance | undefined {
    return types[type];
}

export function displayNameOf(type: string): string {
    return types[type]?.displayName ?? type;
}

export function libraryOf(type: string): string {
    return types[type]?.library ?? 'Other';
}

/** Whether Hopsan draws the type's graphic upright whatever the component's rotation and flip. */
export function keepsIconUpright(type: string): boolean {
    return types[type]?.upright === true;
}
