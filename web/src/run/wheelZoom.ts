// Zooming and panning a time plot with the mouse, as in Hopsan: the wheel zooms the time axis
// about the pointer (with Shift the y axes); a drag with the middle button, or with the left
// button while Ctrl (⌘) is held, pans; a double click shows the whole run again. A plain left
// drag still zooms to the dragged span (uPlot's own), and the two cursors keep their drags.
import type uPlot from 'uplot';
import type { SavedZoom } from './runHistory';
import { keepWithin, panBy, wheelFactor, zoomAbout, type Range } from './zoomRange';

interface Drag { pointer: number; x: number; y: number; ranges: Map<string, Range> }

const rangeOf = (u: uPlot, key: string): Range | null => {
    const { min, max } = u.scales[key];
    return min === undefined || max === undefined ? null : [min, max];
};

/** The times of the plot's samples, first to last. */
function wholeRun(u: uPlot): Range | null {
    const xs = u.data[0];
    return xs.length === 0 ? null : [xs[0], xs[xs.length - 1]];
}

export class WheelZoom {
    /**
     * y scales the user zoomed or panned: they keep their range when the time range changes,
     * instead of fitting the curves in view again.
     */
    private readonly pinned = new Set<string>();
    private drag: Drag | null = null;

    /**
     * `changed` is told after the user zoomed or panned (by wheel, drag or double click) or
     * zoomed to a dragged span; `yUnits` names the unit of each y scale's values, which a saved
     * zoom keys its y ranges by.
     */
    constructor(private readonly changed: () => void, private readonly yUnits: ReadonlyMap<string, string>) {}

    /** The uPlot plugin: pinnable y scales and the mouse's handlers. */
    plugin(): uPlot.Plugin {
        return {
            opts: (_u, opts) => {
                const scales = { ...opts.scales };
                for (const key of new Set(opts.series.slice(1).map((s) => s.scale ?? 'y'))) {
                    scales[key] = { ...scales[key], auto: () => !this.pinned.has(key) };
                }
                return { ...opts, scales };
            },
            hooks: {
                init: (u) => this.listen(u),
                // uPlot's drag zoom, once the button is let go
                setSelect: () => this.changed(),
            },
        };
    }

    /** The zoom to remember: the time shown and the y ranges the user zoomed; none when the whole run shows. */
    saved(u: uPlot): SavedZoom | undefined {
        const x = rangeOf(u, 'x');
        const whole = wholeRun(u);
        if (!x || !whole) return undefined;
        const tolerance = (whole[1] - whole[0]) * 1e-9;
        const y = Object.fromEntries([...this.yRanges(u)].flatMap(([key, range]) => (this.yUnits.has(key) ? [[this.yUnits.get(key)!, range]] : [])));
        const narrower = x[0] > whole[0] + tolerance || x[1] < whole[1] - tolerance;
        if (!narrower && Object.keys(y).length === 0) return undefined;
        return Object.keys(y).length > 0 ? { x, y } : { x };
    }

    /** Shows a saved zoom again: its time (kept within the run) and its y ranges on the axes of the same units. */
    restore(u: uPlot, zoom: SavedZoom): void {
        const whole = wholeRun(u);
        u.batch(() => {
            if (whole) {
                const [min, max] = keepWithin(zoom.x, whole);
                u.setScale('x', { min, max });
            }
            for (const [key, unit] of this.yUnits) {
                const range = zoom.y?.[unit];
                if (!range) continue;
                this.pinned.add(key);
                u.setScale(key, { min: range[0], max: range[1] });
            }
        });
    }

    private yRanges(u: uPlot): Map<string, Range> {
        const ranges = new Map<string, Range>();
        for (const key of this.pinned) {
            const range = rangeOf(u, key);
            if (range) ranges.set(key, range);
        }
        return ranges;
    }

    private listen(u: uPlot): void {
        const over = u.over;
        over.addEventListener('wheel', (e) => this.wheel(u, e), { passive: false });
        over.addEventListener('pointerdown', (e) => this.grab(u, e));
        over.addEventListener('pointermove', (e) => this.pan(u, e));
        over.addEventListener('pointerup', (e) => this.release(u, e));
        over.addEventListener('pointercancel', (e) => this.release(u, e));
        // uPlot's double click (handled before this) fits the time axis to the run; the y axes fit the curves again
        over.addEventListener('dblclick', () => {
            const x = rangeOf(u, 'x');
            if (this.pinned.size > 0 && x) {
                this.pinned.clear();
                u.setScale('x', { min: x[0], max: x[1] });
            }
            this.changed();
        });
        // no paste or scrolling mode at the end of a middle-button pan
        over.addEventListener('auxclick', (e) => e.preventDefault());
    }

    private yScales(u: uPlot): string[] {
        return [...new Set(u.series.slice(1).filter((s) => s.show !== false).map((s) => s.scale ?? 'y'))];
    }

    private wheel(u: uPlot, e: WheelEvent): void {
        const whole = wholeRun(u);
        if (!whole) return;
        e.preventDefault();
        // with Shift held, some browsers turn the wheel sideways
        const factor = wheelFactor(e.deltaY !== 0 ? e.deltaY : e.deltaX, e.deltaMode, u.over.clientHeight);
        const box = u.over.getBoundingClientRect();
        u.batch(() => {
            if (e.shiftKey) {
                for (const key of this.yScales(u)) {
                    const range = rangeOf(u, key);
                    if (!range) continue;
                    const [min, max] = zoomAbout(range, u.posToVal(e.clientY - box.top, key), factor);
                    this.pinned.add(key);
                    u.setScale(key, { min, max });
                }
            } else {
                const range = rangeOf(u, 'x');
                if (!range) return;
                const [min, max] = keepWithin(zoomAbout(range, u.posToVal(e.clientX - box.left, 'x'), factor), whole);
                u.setScale('x', { min, max });
            }
        });
        this.changed();
    }

    private grab(u: uPlot, e: PointerEvent): void {
        const panning = e.button === 1 || (e.button === 0 && (e.ctrlKey || e.metaKey));
        if (!panning) return;
        const x = rangeOf(u, 'x');
        if (!x) return;
        // not uPlot's drag zoom (a cancelled pointerdown sends no mousedown), nor the middle button's scrolling
        e.preventDefault();
        u.over.setPointerCapture(e.pointerId);
        const ranges = new Map<string, Range>([['x', x], ...this.yRanges(u)]);
        this.drag = { pointer: e.pointerId, x: e.clientX, y: e.clientY, ranges };
    }

    // the curves follow the pointer: the time axis, and the y axes the user zoomed
    private pan(u: uPlot, e: PointerEvent): void {
        const drag = this.drag;
        const whole = wholeRun(u);
        if (!drag || e.pointerId !== drag.pointer || !whole) return;
        const width = u.over.clientWidth;
        const height = u.over.clientHeight;
        u.batch(() => {
            for (const [key, range] of drag.ranges) {
                const [from, to] = range;
                const [min, max] = key === 'x'
                    ? keepWithin(panBy(range, -(e.clientX - drag.x) * (to - from) / width), whole)
                    : panBy(range, (e.clientY - drag.y) * (to - from) / height);
                u.setScale(key, { min, max });
            }
        });
    }

    private release(u: uPlot, e: PointerEvent): void {
        if (!this.drag || e.pointerId !== this.drag.pointer) return;
        this.drag = null;
        if (u.over.hasPointerCapture(e.pointerId)) u.over.releasePointerCapture(e.pointerId);
        this.changed();
    }
}
