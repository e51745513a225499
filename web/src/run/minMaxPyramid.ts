// The smallest and largest value of a curve over any range of its samples, found in a time that
// grows with the logarithm of the range: level k holds the minimum and maximum of each aligned
// block of 16·2^k samples, and a range is covered by the largest blocks that fit in it, with at
// most 15 samples walked at each end. (Blocks of 16 keep the pyramid an eighth of the curve's size.)

const BLOCK = 16;

type Ys = ArrayLike<number | null | undefined>;

/** The smallest and largest value of `ys[from … to]`, walked one by one, gaps left out; [Infinity, -Infinity] if all are gaps. */
export function walkedRange(ys: Ys, from: number, to: number): [number, number] {
    let lowest = Infinity;
    let highest = -Infinity;
    for (let i = from; i <= to; ++i) {
        const y = ys[i];
        // (a NaN fails both comparisons)
        if (typeof y !== 'number') continue;
        if (y < lowest) lowest = y;
        if (y > highest) highest = y;
    }
    return [lowest, highest];
}

export class MinMaxPyramid {
    /** lows[k][j]: the smallest value of samples j·16·2^k … (j + 1)·16·2^k − 1 (Infinity where all are gaps). */
    private readonly lows: Float64Array[] = [];
    private readonly highs: Float64Array[] = [];

    /** `ys` with gaps (null, NaN), which are left out; they must not change while the pyramid is used. */
    constructor(private readonly ys: Ys) {
        let low = new Float64Array(Math.ceil(ys.length / BLOCK));
        let high = new Float64Array(low.length);
        for (let j = 0; j < low.length; ++j) [low[j], high[j]] = walkedRange(this.ys, j * BLOCK, Math.min(ys.length, (j + 1) * BLOCK) - 1);
        while (low.length > 0) {
            this.lows.push(low);
            this.highs.push(high);
            if (low.length === 1) break;
            const blocks = Math.ceil(low.length / 2);
            const nextLow = new Float64Array(blocks);
            const nextHigh = new Float64Array(blocks);
            for (let j = 0; j < blocks; ++j) {
                // a last block may have one half only
                const second = Math.min(2 * j + 1, low.length - 1);
                nextLow[j] = Math.min(low[2 * j], low[second]);
                nextHigh[j] = Math.max(high[2 * j], high[second]);
            }
            low = nextLow;
            high = nextHigh;
        }
    }

    /** The smallest and largest value of samples `from` … `to`; [Infinity, -Infinity] if all are gaps. */
    range(from: number, to: number): [number, number] {
        // whole blocks first … last; the samples around them one by one
        const first = Math.ceil(Math.max(0, from) / BLOCK);
        const last = Math.floor((to + 1) / BLOCK) - 1;
        if (first > last) return walkedRange(this.ys, from, to);
        let [lowest, highest] = walkedRange(this.ys, from, first * BLOCK - 1);
        const [tailLow, tailHigh] = walkedRange(this.ys, (last + 1) * BLOCK, to);
        lowest = Math.min(lowest, tailLow);
        highest = Math.max(highest, tailHigh);
        for (let j = first; j <= last;) {
            // the largest block that starts at j and ends by `last`
            const aligned = j === 0 ? 31 : 31 - Math.clz32(j & -j);
            const k = Math.min(aligned, 31 - Math.clz32(last - j + 1), this.lows.length - 1);
            lowest = Math.min(lowest, this.lows[k][j >> k]);
            highest = Math.max(highest, this.highs[k][j >> k]);
            j += 2 ** k;
        }
        return [lowest, highest];
    }
}
