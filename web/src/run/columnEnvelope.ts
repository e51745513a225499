// Which samples of a long curve to draw so that it looks the same at the plot's width: in each
// pixel column the first, the lowest, the highest and the last sample. The line between columns
// then joins the same points as the whole curve's, and within a column it spans the same values,
// so the drawn envelope is the original's, from at most four points per column.

/** The first index in `lo` … `hi` whose time is not before `t` (`hi` + 1 if none). */
function firstFrom(xs: ArrayLike<number>, t: number, lo: number, hi: number): number {
    let a = lo;
    let b = hi + 1;
    while (a < b) {
        const mid = (a + b) >> 1;
        if (xs[mid] < t) a = mid + 1; else b = mid;
    }
    return a;
}

/**
 * The indices, in order, of the samples `from` … `to` to draw in `columns` pixel columns
 * spanning `xMin` … `xMax`: per column its first, lowest, highest and last sample. `xs` are
 * sorted times; a NaN in `ys` is a gap, skipped (the line joins the samples around it).
 * Samples before `xMin` and from `xMax` on count as a column each.
 */
export function columnEnvelope(xs: ArrayLike<number>, ys: ArrayLike<number>, from: number, to: number,
    xMin: number, xMax: number, columns: number): Int32Array {
    const kept = new Int32Array(4 * (columns + 2));
    let count = 0;
    // one column: the times are found by halving, then only its values are walked
    const gather = (a: number, b: number) => {
        let first = -1;
        let last = -1;
        let low = -1;
        let high = -1;
        let lowest = Infinity;
        let highest = -Infinity;
        for (let i = a; i <= b; ++i) {
            const y = ys[i];
            if (Number.isNaN(y)) continue;
            if (first < 0) first = i;
            last = i;
            if (y < lowest) {
                lowest = y;
                low = i;
            }
            if (y > highest) {
                highest = y;
                high = i;
            }
        }
        if (first < 0) return;
        // first and last are the outermost; the lowest and highest in their order between
        const [c, d] = low <= high ? [low, high] : [high, low];
        kept[count++] = first;
        if (c !== first) kept[count++] = c;
        if (d !== c) kept[count++] = d;
        if (last !== d) kept[count++] = last;
    };
    const step = (xMax - xMin) / columns;
    let start = from;
    for (let column = -1; column < columns; ++column) {
        const end = firstFrom(xs, column === columns - 1 ? xMax : xMin + (column + 1) * step, start, to);
        gather(start, end - 1);
        start = end;
    }
    gather(start, to);
    return kept.subarray(0, count);
}
