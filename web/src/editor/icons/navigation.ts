// Navigation blocks: earth coordinates as a globe, a waypoint as a map pin at the end of a
// dashed course, the state monitor as its row of lamps, and the time accelerator as a clock
// with the fast-forward sign.
import { Pen, type Glyph } from './draw';

export function globe(p: Pen): Glyph {
    const r = p.u * 0.75;
    return [
        p.circle([0, 0], r, { cls: 'glyph-globe', fill: '#fff' }),
        p.ellipse([0, 0], r * 0.45, r, { cls: 'glyph-meridian' }),
        p.line([[0, -r], [0, r]], { cls: 'glyph-meridian' }),
        p.line([[-r, 0], [r, 0]], { cls: 'glyph-parallel' }),
        p.line([[-r * 0.87, -r * 0.5], [r * 0.87, -r * 0.5]], { cls: 'glyph-parallel', faint: true }),
        p.line([[-r * 0.87, r * 0.5], [r * 0.87, r * 0.5]], { cls: 'glyph-parallel', faint: true }),
    ];
}

/** A map pin (a drop with a hole) at the end of a dashed course. */
export function waypoint(p: Pen): Glyph {
    const { w, h } = p;
    const r = Math.min(h * 0.38, w * 0.3);
    const [cx, cy] = [w * 0.35, -h * 0.25];
    const tip = h * 0.75;
    // the drop's sides touch the circle where the tangents from the tip do
    const a = Math.acos(Math.min(1, r / (tip - cy)));
    return [
        p.line([[-w * 0.8, h * 0.7], [-w * 0.3, h * 0.2], [cx - r * 0.3, tip * 0.9]], { cls: 'glyph-course', dashed: true }),
        p.poly([[cx, tip], ...Pen.arc([cx, cy], r, Math.PI / 2 + a, Math.PI * 2.5 - a, 16)], { cls: 'glyph-pin', fill: '#fff' }),
        p.circle([cx, cy], r * 0.38, { cls: 'glyph-pin' }),
    ];
}

/** The state monitor: a row of three lamps, the first lit. */
export function stateMonitor(p: Pen): Glyph {
    const { w, h } = p;
    const r = Math.min(h * 0.35, w * 0.15);
    return [-1, 0, 1].map((i) => p.circle([i * w * 0.4, 0], r, i === -1 ? { filled: true } : { cls: 'glyph-lamp', fill: '#fff' }));
}

/** A clock face beside the fast-forward sign. */
export function timeAccelerator(p: Pen): Glyph {
    const { w, h } = p;
    const r = Math.min(h * 0.7, w * 0.35);
    const c: [number, number] = [-w * 0.4, 0];
    const t = r * 0.8;
    const x = w * 0.15;
    return [
        p.circle(c, r, { cls: 'glyph-clock', fill: '#fff' }),
        p.line([[c[0], c[1] - r * 0.7], c, [c[0] + r * 0.5, c[1]]], { cls: 'glyph-hands' }),
        p.poly([[x, -t], [x + t, 0], [x, t]], { filled: true }),
        p.poly([[x + t, -t], [x + 2 * t, 0], [x + t, t]], { filled: true }),
    ];
}
