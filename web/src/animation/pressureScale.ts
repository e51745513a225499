// The colour scale of line pressures: blue at the low end of the range to red at the high end,
// as in Hopsan's animation, through cyan, green and yellow so that middle pressures are told
// apart too. The range is the one seen so far unless the user fixes it.

/** Colour stops from low to high (fractions 0, 1/4, …, 1). */
export const SCALE_STOPS: [number, number, number][] = [
    [33, 64, 214], [18, 160, 200], [40, 170, 70], [235, 175, 0], [214, 32, 32],
];

/** The colour of `fraction` (0 low … 1 high, clamped) as #rrggbb. */
export function scaleColour(fraction: number): string {
    const f = Math.max(0, Math.min(1, Number.isFinite(fraction) ? fraction : 0)) * (SCALE_STOPS.length - 1);
    const i = Math.min(SCALE_STOPS.length - 2, Math.floor(f));
    const t = f - i;
    const [a, b] = [SCALE_STOPS[i], SCALE_STOPS[i + 1]];
    const hex = (k: number) => Math.round(a[k] + (b[k] - a[k]) * t).toString(16).padStart(2, '0');
    return `#${hex(0)}${hex(1)}${hex(2)}`;
}

/** A CSS linear-gradient of the scale (for the legend). */
export function scaleGradient(direction = 'to right'): string {
    return `linear-gradient(${direction}, ${SCALE_STOPS.map((c, i) => `rgb(${c.join(',')}) ${(100 * i) / (SCALE_STOPS.length - 1)}%`).join(', ')})`;
}

/**
 * The pressure range the colours span: automatic (it widens to every pressure shown; it starts
 * at 0 as Hopsan's does, so that a tank line is blue) or fixed by the user.
 */
export class PressureRange {
    min = 0;
    max = 0;
    auto = true;

    /** Widens an automatic range to hold `p`; true when it changed. */
    see(p: number): boolean {
        if (!this.auto || !Number.isFinite(p)) return false;
        if (p < this.min) { this.min = p; return true; }
        if (p > this.max) { this.max = p; return true; }
        return false;
    }

    /** Fixes the range (the user's, or a run's whole range); `auto` false keeps it there. */
    set(min: number, max: number, auto = false): void {
        [this.min, this.max, this.auto] = [Math.min(min, max), Math.max(min, max), auto];
    }

    /** Where `p` lies in the range, 0 … 1 (a range of no width: 0). */
    fraction(p: number): number {
        const span = this.max - this.min;
        return span > 0 ? (p - this.min) / span : 0;
    }

    colour(p: number): string { return scaleColour(this.fraction(p)); }
}

/**
 * The pressure range of a recorded run for its colours: from 0 (a tank line is blue) to the
 * highest pressure but for the top 1 % of samples, so that a start-up peak does not leave every
 * line blue for the rest of the run.
 */
export function runPressureRange(columns: Iterable<ArrayLike<number>>): [number, number] {
    const all: number[] = [];
    for (const c of columns) for (let i = 0; i < c.length; ++i) if (Number.isFinite(c[i])) all.push(c[i]);
    if (all.length === 0) return [0, 0];
    all.sort((a, b) => a - b);
    const high = all[Math.min(all.length - 1, Math.floor(all.length * 0.99))];
    return [Math.min(0, all[0]), Math.max(0, high)];
}
