// Units on plot axes: which unit a logged variable has, SI prefixes for the tick labels
// (1.2e7 Pa reads 12 MPa), and the axes of a plot (one per unit, four before the user is asked).
import { nodeVariables } from '../model/nodeTypes';

/** The unit of "Comp#Port#Var" when every node type that has `Var` agrees on it ('' if unknown). */
export function unitOfVariable(name: string): string {
    const variable = name.slice(name.lastIndexOf('#') + 1);
    const units = new Set(Object.values(nodeVariables).flat().filter((v) => v.name === variable).map((v) => v.unit));
    return units.size === 1 ? [...units][0] : '';
}

const PREFIXES: [number, string][] = [[1e9, 'G'], [1e6, 'M'], [1e3, 'k'], [1, ''], [1e-3, 'm'], [1e-6, 'µ'], [1e-9, 'n']];

// a prefix is right only on a plain unit or the first factor of a quotient (mm/s, not mm^3/s)
function takesPrefix(unit: string): boolean {
    return /^(Pa|m|N|W|V|A|J|Hz|s|g)(\/.*)?$/.test(unit);
}

export interface Prefixed { factor: number; unit: string }

/** The prefix that puts `largest` (the largest absolute value shown) between 1 and 1000. */
export function siPrefix(largest: number, unit: string): Prefixed {
    if (!takesPrefix(unit) || !(largest > 0) || !Number.isFinite(largest)) return { factor: 1, unit };
    const [factor, prefix] = PREFIXES.find(([f]) => largest >= f * 0.9995) ?? PREFIXES[PREFIXES.length - 1];
    return { factor, unit: `${prefix}${unit}` };
}

/** Axes a plot window takes on its own; a variable of one more unit asks the user where it goes. */
export const MAX_AXES = 4;

/** Units in order of first appearance; the series of each unit share one axis. */
export function axisUnits(units: string[]): string[] {
    return [...new Set(units)];
}
