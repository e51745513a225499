// The range maths of zooming and panning a plot axis with the mouse: a wheel step scales the
// shown range about the value under the pointer (which stays under it), a drag shifts it, and
// the time axis never leaves the run.

export type Range = [number, number];

/** How much one wheel event scales the shown range: > 1 zooms out (wheel towards the user), < 1 in. */
export function wheelFactor(deltaY: number, deltaMode: number, pageHeight: number): number {
    // lines and pages as the pixels a browser scrolls for them
    const pixels = deltaMode === 1 ? deltaY * 16 : deltaMode === 2 ? deltaY * pageHeight : deltaY;
    // a notch of a common wheel (100 px) shows about a fifth more or less
    return Math.exp(Math.max(-500, Math.min(500, pixels)) * 0.002);
}

/** `range` scaled by `factor` about `anchor`: the anchor keeps its place in the range. */
export function zoomAbout([min, max]: Range, anchor: number, factor: number): Range {
    return [anchor - (anchor - min) * factor, anchor + (max - anchor) * factor];
}

/** `range` shifted by `delta`. */
export function panBy([min, max]: Range, delta: number): Range {
    return [min + delta, max + delta];
}

/**
 * `range` kept inside `whole`: no wider than it, shifted back inside when it sticks out, and
 * no narrower than a millionth of it (beyond which the ticks stop making sense).
 */
export function keepWithin([min, max]: Range, [first, last]: Range): Range {
    const whole = last - first;
    const width = Math.min(whole, Math.max(max - min, whole * 1e-6));
    if (!(whole > 0)) return [first, last];
    const centre = (min + max) / 2;
    const start = Math.min(last - width, Math.max(first, centre - width / 2));
    return [start, start + width];
}
