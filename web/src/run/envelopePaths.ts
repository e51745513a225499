// A uPlot line for curves of many samples: when a curve has far more samples in view than the
// plot has pixel columns, it is drawn through the few samples that shape it at that width
// (columnEnvelope), so zooming out over a long run stays fast. The chart's data keep every
// sample, so the read-outs, the cursors and the CSV are as logged.
import uPlot from 'uplot';
import { columnEnvelope } from './columnEnvelope';

/**
 * Samples in view per pixel column beyond which a curve is drawn through its envelope; below
 * it uPlot's own line, which also draws a column's extremes, walks them about as fast.
 */
const SAMPLES_PER_COLUMN = 16;

/** A path builder for every series of one chart. */
export function envelopePaths(): uPlot.Series.PathBuilder {
    const everySample = uPlot.paths.linear!();
    // the chart's columns as typed arrays (gaps NaN), walked faster than its mixed ones; made
    // once per data, and let go with them. Data drawn once only (each frame of a streaming run)
    // are drawn by uPlot's line: a copy pays off from the second time.
    const typed = new WeakMap<object, Float64Array>();
    const seen = new WeakSet<object>();
    const typedOf = (values: ArrayLike<number | null | undefined>) => {
        let array = typed.get(values);
        if (!array) {
            array = new Float64Array(values.length);
            for (let i = 0; i < values.length; ++i) array[i] = values[i] ?? NaN;
            typed.set(values, array);
        }
        return array;
    };
    return (u, seriesIdx, idx0, idx1) => {
        const columns = Math.round(u.bbox.width);
        const { min: xMin, max: xMax } = u.scales.x;
        const logged = u.data[seriesIdx];
        const again = seen.has(logged);
        seen.add(logged);
        if (!again || idx1 - idx0 < SAMPLES_PER_COLUMN * columns || xMin === undefined || xMax === undefined || !(xMax > xMin)) {
            return everySample(u, seriesIdx, idx0, idx1);
        }
        const xs = typedOf(u.data[0]);
        const ys = typedOf(logged);
        const scale = u.series[seriesIdx].scale ?? 'y';
        const stroke = new Path2D();
        let started = false;
        for (const i of columnEnvelope(xs, ys, idx0, idx1, xMin, xMax, columns)) {
            const x = u.valToPos(xs[i], 'x', true);
            const y = u.valToPos(ys[i], scale, true);
            if (started) stroke.lineTo(x, y);
            else stroke.moveTo(x, y);
            started = true;
        }
        return { stroke, flags: 0 };
    };
}
