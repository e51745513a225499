// Which physical quantity a logged variable is, so that its display unit can be chosen.
import { UNIT_SCALES } from './unitScales';

/**
 * The quantity of variable "Comp#Port#Var" whose base unit is `base`. Several quantities share a
 * base unit (rad/s: Frequency and AngularVelocity); Hopsan's node variables are named after their
 * quantity (AngularVelocity, Pressure), which decides. Null when nothing decides.
 */
export function quantityOf(variable: string, base: string): string | null {
    const candidates = UNIT_SCALES.filter((q) => q.base === base).map((q) => q.quantity);
    const name = variable.slice(variable.lastIndexOf('#') + 1);
    if (candidates.includes(name)) return name;
    return candidates.length === 1 ? candidates[0] : null;
}
