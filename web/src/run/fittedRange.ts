// A y axis's range fitted to its curves in view, as uPlot fits it (a tenth of padding), but read
// from a pyramid of block minima and maxima per curve: uPlot walks every sample in view on each
// frame, 1.6 million for 16 curves of a long run zoomed out. The chart's series must not be
// ranged by uPlot (`auto: false`).
import uPlot from 'uplot';
import { MinMaxPyramid, walkedRange } from './minMaxPyramid';

/** The range function for the y scales of one chart; each curve's pyramid is made once per data. */
export function fittedRange(): uPlot.Range.Function {
    // keyed by the series' values: new data get a new pyramid, old ones are let go. Data ranged
    // once only (each frame of a streaming run) are walked: a pyramid pays off from the second time.
    const pyramids = new WeakMap<object, MinMaxPyramid>();
    const seen = new WeakSet<object>();
    return (u, _min, _max, key) => {
        // the samples in view, as uPlot found them for this range
        const [from, to] = u.series[0].idxs ?? [0, u.data[0].length - 1];
        let lowest = Infinity;
        let highest = -Infinity;
        u.series.forEach((s, i) => {
            if (i === 0 || s.scale !== key || s.show === false || from === null || to === null) return;
            const ys = u.data[i];
            let pyramid = pyramids.get(ys);
            if (!pyramid && seen.has(ys)) {
                pyramid = new MinMaxPyramid(ys);
                pyramids.set(ys, pyramid);
            }
            seen.add(ys);
            const [low, high] = pyramid ? pyramid.range(from, to) : walkedRange(ys, from, to);
            lowest = Math.min(lowest, low);
            highest = Math.max(highest, high);
        });
        return lowest <= highest ? uPlot.rangeNum(lowest, highest, 0.1, true) : [0, 1];
    };
}
