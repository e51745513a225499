// Display units of a quantity and the conversion between them and the base unit (the unit the
// server logs). Hopsan's rule: base = scale * display + offset; the offset makes °C and °F affine.
import { UNIT_SCALES } from './unitScales';

export interface DisplayUnit { name: string; scale: number; offset: number }

/** The units a quantity can be shown in: its base unit first, then Hopsan's others. */
export function displayUnitsOf(quantity: string): DisplayUnit[] {
    const entry = UNIT_SCALES.find((q) => q.quantity === quantity);
    if (!entry) return [];
    return [{ name: entry.base, scale: 1, offset: 0 }, ...entry.units.map((u) => ({ name: u.name, scale: u.scale, offset: u.offset ?? 0 }))];
}

/** The unit `name` of `quantity`, or null when the quantity has no such unit. */
export function findDisplayUnit(quantity: string, name: string): DisplayUnit | null {
    return displayUnitsOf(quantity).find((u) => u.name === name) ?? null;
}

export function toDisplay(base: number, unit: DisplayUnit): number {
    return (base - unit.offset) / unit.scale;
}

export function fromDisplay(display: number, unit: DisplayUnit): number {
    return unit.scale * display + unit.offset;
}

/** A series of base-unit values in `unit`. */
export function toDisplayValues(values: number[], unit: DisplayUnit): number[] {
    return values.map((v) => toDisplay(v, unit));
}
