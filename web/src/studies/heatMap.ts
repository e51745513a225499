// A 2-D sweep as a heat map: the grid's cells (x: one parameter, y: another, colour: an output)
// and the colour scale. Pure, so the drawing (HeatMapView.ts) only paints what this computes.
import type { StudyTable } from './studyTypes';

export interface HeatMapGrid {
    xName: string; yName: string; zName: string;
    /** The distinct values of each axis, ascending. */
    xs: number[]; ys: number[];
    /** z[iy][ix]; null where the run failed or is not done. */
    z: (number | null)[][];
    /** The range of the finite z values; null when there is none. */
    range: [number, number] | null;
}

/** The distinct values of a column, ascending. */
export function distinctValues(table: StudyTable, column: string): number[] {
    const i = table.columns.indexOf(column);
    return [...new Set(table.rows.map((r) => r[i]).filter((v): v is number => typeof v === 'number'))].sort((a, b) => a - b);
}

/**
 * The grid of `zName` over `xName` × `yName`; null when a column is missing. With more than two
 * swept parameters, `fixed` holds the others at one value each (a slice of the grid), so no
 * cell is painted over by a run of another slice.
 */
export function heatMapGrid(table: StudyTable, xName: string, yName: string, zName: string, fixed: Record<string, number> = {}): HeatMapGrid | null {
    const [xi, yi, zi] = [xName, yName, zName].map((n) => table.columns.indexOf(n));
    if (xi < 0 || yi < 0 || zi < 0) return null;
    const xs = distinctValues(table, xName);
    const ys = distinctValues(table, yName);
    const z: (number | null)[][] = ys.map(() => xs.map(() => null));
    let lo = Infinity;
    let hi = -Infinity;
    const held = Object.entries(fixed).map(([name, value]) => [table.columns.indexOf(name), value] as const).filter(([i]) => i >= 0 && i !== xi && i !== yi);
    for (const r of table.rows) {
        if (held.some(([i, value]) => r[i] !== value)) continue;
        const value = r[zi];
        if (typeof r[xi] !== 'number' || typeof r[yi] !== 'number' || typeof value !== 'number' || !Number.isFinite(value)) continue;
        z[ys.indexOf(r[yi] as number)][xs.indexOf(r[xi] as number)] = value;
        lo = Math.min(lo, value);
        hi = Math.max(hi, value);
    }
    return { xName, yName, zName, xs, ys, z, range: lo <= hi ? [lo, hi] : null };
}

// viridis at 9 stops: perceptually even and readable in grey and by most colour-blind readers
const STOPS: [number, number, number][] = [
    [68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141], [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37],
];

/** The colour of `t` in [0, 1] (clamped), as `rgb(r, g, b)`. */
export function colourAt(t: number): string {
    const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (STOPS.length - 1);
    const i = Math.min(STOPS.length - 2, Math.floor(x));
    const f = x - i;
    const [a, b] = [STOPS[i], STOPS[i + 1]];
    const c = a.map((v, k) => Math.round(v + f * (b[k] - v)));
    return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
}

/** Where `value` sits in the range, 0 to 1 (0.5 for a range of one value). */
export function scaleOf(value: number, range: [number, number]): number {
    return range[1] === range[0] ? 0.5 : (value - range[0]) / (range[1] - range[0]);
}

export interface Cell { ix: number; iy: number; x: number; y: number; width: number; height: number; value: number | null }

/**
 * The cells in a plot box (pixels, y down): equal widths per distinct value, the first y value
 * at the bottom, as on a graph.
 */
export function heatMapCells(grid: HeatMapGrid, box: { left: number; top: number; width: number; height: number }): Cell[] {
    const w = box.width / Math.max(1, grid.xs.length);
    const hgt = box.height / Math.max(1, grid.ys.length);
    return grid.ys.flatMap((_, iy) => grid.xs.map((__, ix) => ({
        ix, iy, x: box.left + ix * w, y: box.top + box.height - (iy + 1) * hgt, width: w, height: hgt, value: grid.z[iy][ix],
    })));
}

/** Whether the runs fill most cells of their grid (a grid sweep), rather than a diagonal (list) or scattered samples (random). */
export function formsGrid(grid: HeatMapGrid): boolean {
    const filled = grid.z.flat().filter((v) => v !== null).length;
    return grid.xs.length > 1 && grid.ys.length > 1 && filled * 2 >= grid.xs.length * grid.ys.length;
}
