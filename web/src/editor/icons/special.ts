// Blocks of the special, experimental and benchmarking folders: the 2D signal bus, the circular
// segment (area from a depth), a NumHop script as a page of text, a pass-through dummy, an
// optimization test function as its contour lines around the optimum, and a subsystem's port.
import { Pen, portsOf, type Glyph } from './draw';

/** 2D signal bus blocks: the bus as a bar on its port's side, the two single signals joining it. */
export function signalBus(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const ports = portsOf(type, w, h);
    const bus = ports.find((q) => q.name === 'P2d')?.at[0] ?? w;
    const x = Math.sign(bus) * w * 0.3;
    const out: Glyph = [p.line([[x, -h * 0.8], [x, h * 0.8]], { cls: 'glyph-bus' }), p.line([[x, 0], [bus, 0]], { cls: 'glyph-bus' })];
    for (const { name, at } of ports) if (name !== 'P2d') out.push(p.line([at, [x, at[1]]], { cls: 'glyph-port-line' }));
    return out;
}

/** A circle with a segment cut off by a chord and filled: the area a depth into a circle covers. */
export function circularSegment(p: Pen, type: string): Glyph {
    const r = p.u * 0.72;
    const depth = r * 0.55;
    const y = r - depth;
    const a = Math.asin(y / r);
    const out: Glyph = [p.circle([0, 0], r, { cls: 'glyph-circle' }), p.poly(Pen.arc([0, 0], r, a, Math.PI - a, 12), { cls: 'glyph-segment', filled: true })];
    // the derivative block marks the chord it moves
    if (/Dx/.test(type)) out.push(...p.arrow([r * 0.95, -r * 0.1], [r * 0.95, y + r * 0.05], 'glyph-arrow', r * 0.3));
    return out;
}

/** A script: a page with a folded corner and lines of text. */
export function script(p: Pen): Glyph {
    const { w, h } = p;
    const [x0, y0] = [Math.min(w * 0.5, h * 0.7), h * 0.8];
    const fold = x0 * 0.45;
    const out: Glyph = [p.poly([[-x0, -y0], [x0 - fold, -y0], [x0, -y0 + fold], [x0, y0], [-x0, y0]], { cls: 'glyph-page', fill: '#fff' }),
        p.line([[x0 - fold, -y0], [x0 - fold, -y0 + fold], [x0, -y0 + fold]], { cls: 'glyph-page' })];
    for (const [i, len] of [0.9, 1.2, 0.7].entries()) out.push(p.line([[-x0 * 0.65, -y0 * 0.2 + i * y0 * 0.35], [-x0 * 0.65 + x0 * len, -y0 * 0.2 + i * y0 * 0.35]], { faint: true }));
    return out;
}

/** A dummy: an empty dashed box the signal or line passes straight through. */
export function passThrough(p: Pen): Glyph {
    const { w, h } = p;
    return [p.rect(-w * 0.5, -h * 0.6, w * 0.5, h * 0.6, { dashed: true, cls: 'glyph-dummy' }), p.line([[-w, 0], [w, 0]], { cls: 'glyph-port-line' })];
}

/** An optimization test function: contour lines around its optimum, marked with a cross. */
export function contours(p: Pen): Glyph {
    const { w, h } = p;
    const c: [number, number] = [w * 0.1, -h * 0.05];
    const out: Glyph = [1, 0.68, 0.36].map((k, i) => p.ellipse([c[0] - (1 - k) * w * 0.15, c[1]], w * 0.7 * k, h * 0.7 * k, { cls: 'glyph-contour', faint: i === 0 }));
    const m = p.u * 0.08;
    out.push(p.line([[c[0] - m, c[1] - m], [c[0] + m, c[1] + m]], { cls: 'glyph-optimum' }), p.line([[c[0] - m, c[1] + m], [c[0] + m, c[1] - m]], { cls: 'glyph-optimum' }));
    return out;
}

/** A subsystem's port: the diamond the canvas draws for it. */
export function systemPort(p: Pen): Glyph {
    const r = p.u * 0.85;
    return [p.poly([[-r, 0], [0, -r], [r, 0], [0, r]], { cls: 'glyph-system-port', fill: '#fff' }), p.circle([0, 0], r * 0.4, { filled: true })];
}
