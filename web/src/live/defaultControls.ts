// The controls live mode gives Hopsan's interactive components (interactiveTypes.ts) on its
// own: a slider for a valve's spool or a slider block, a switch for a switch, bound to the
// component's input among what live.set may change, under the component. None for an input
// fed by a connection (the server does not offer it), nor where a saved control binds it.
import type { System } from '../protocol/types';
import type { SystemPath } from '../model/modelState';
import { INTERACTIVE_TYPES } from './interactiveTypes';
import type { LiveControl } from './liveControls';

/** Below the component's centre, in drawing units: clear of a usual icon. */
const BELOW = 48;

/** The live value a component's input port goes by: `Comp.port#Value` or `Comp.port`. */
export function liveValueOfPort(component: string, port: string, dataname: string, liveNames: ReadonlySet<string>): string | null {
    return [`${component}.${port}#${dataname}`, `${component}.${port}`].find((n) => liveNames.has(n)) ?? null;
}

export function defaultControls(system: System, path: SystemPath, liveNames: ReadonlySet<string>, saved: readonly LiveControl[]): LiveControl[] {
    const bound = new Set(saved.map((c) => c.name));
    const prefix = path.map((p) => `${p}$`).join('');
    return system.components.flatMap((comp): LiveControl[] => {
        const interaction = INTERACTIVE_TYPES[comp.type];
        if (!interaction) return [];
        const name = liveValueOfPort(prefix + comp.name, interaction.port, interaction.dataname, liveNames);
        if (!name || bound.has(name)) return [];
        const at = { x: comp.pose.x, y: comp.pose.y + BELOW, path: [...path] };
        if (interaction.kind === 'switchable') {
            return [{ kind: 'switch', name, min: interaction.off, max: interaction.on, off: interaction.off, on: interaction.on, ...at }];
        }
        const ends = [interaction.min * interaction.gain, interaction.max * interaction.gain];
        // (+ 0: a zero end times a negative gain is -0)
        return [{ kind: 'slider', name, min: Math.min(...ends) + 0, max: Math.max(...ends) + 0, ...at }];
    });
}
