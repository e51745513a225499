// Mechanical symbols of our own: masses (a block with m, hatched ground when it rubs on it),
// springs (zigzag), dampers (dashpot), walls (hatching), inertias (a disc on its shaft),
// torsion springs (a coil on the shaft), gears, pulleys, levers and force/motion sources.
import { Pen, portsOf, type Glyph, type Pt } from './draw';

/** Leads from the box sides to the symbol, on the centre line. */
const leads = (p: Pen, x0: number, x1: number, y = 0): Glyph =>
    [p.line([[-p.w, y], [x0, y]], { cls: 'glyph-port-line' }), p.line([[x1, y], [p.w, y]], { cls: 'glyph-port-line' })];

/** A block with m; one block per mass for multi-mass loads, joined by springs. */
export function mass(pen: Pen, type: string): Glyph {
    const p = pen.upright ? pen.transposed() : pen;
    const { w, h } = p;
    const n = /M3/.test(type) ? 3 : /M2/.test(type) ? 2 : 1;
    const friction = /Friction/.test(type);
    const bh = h * (friction ? 0.55 : 0.7);
    const cy = friction ? -h * 0.2 : 0;
    const bw = n === 1 ? Math.min(w * 0.6, bh * 1.6) : (w * 1.6) / (n * 1.5);
    const out: Glyph = [];
    const xs = Array.from({ length: n }, (_, i) => (n === 1 ? 0 : -w * 0.8 + bw / 2 + (i * (w * 1.6 - bw)) / (n - 1)));
    xs.forEach((x, i) => {
        out.push(p.rect(x - bw / 2, cy - bh, x + bw / 2, cy + bh, { cls: 'glyph-mass', fill: '#fff' }), p.fitText('m', bh * 1.3, bw * 0.4, bh * 0.7, [x, cy]));
        if (i > 0) out.push(p.zigzag([xs[i - 1] + bw / 2, cy], [x - bw / 2, cy], bh * 0.35, 6, 'glyph-spring'));
    });
    if (/Mkc/.test(type)) {
        // Hopsan's mass with spring and damper to the wall: the spring on the left lead
        out.push(p.zigzag([-w * 0.95, cy], [xs[0] - bw / 2, cy], bh * 0.35, 5, 'glyph-spring'), p.line([[xs[n - 1] + bw / 2, cy], [w, cy]], { cls: 'glyph-port-line' }));
    } else out.push(...leads(p, xs[0] - bw / 2, xs[n - 1] + bw / 2, cy));
    if (friction) out.push(...p.hatch([-w * 0.8, cy + bh], [w * 0.8, cy + bh], Math.min(h - bh - Math.abs(cy), h * 0.3) * 0.9, -1, 7));
    return out;
}

export function spring(p: Pen): Glyph {
    const { w, h } = p;
    return [...leads(p, -w * 0.7, w * 0.7), p.zigzag([-w * 0.7, 0], [w * 0.7, 0], h * 0.55, 6, 'glyph-spring')];
}

/** A dashpot: a piston in an open cup. */
export function damper(p: Pen): Glyph {
    const { w, h } = p;
    return [p.line([[-w, 0], [-w * 0.1, 0]]), p.line([[-w * 0.1, -h * 0.4], [-w * 0.1, h * 0.4]]),
        p.line([[-w * 0.45, -h * 0.6], [w * 0.3, -h * 0.6], [w * 0.3, h * 0.6], [-w * 0.45, h * 0.6]]), p.line([[w * 0.3, 0], [w, 0]])];
}

/** A fixed point: a wall at the port with hatching behind it. */
export function fixed(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const port = portsOf(type, w, h)[0]?.at ?? [-w, 0];
    if (p.upright) {
        // wall across the box at the port side, hatch away from the port
        const x = port[0] <= 0 ? -w * 0.5 : w * 0.5;
        const depth = Math.min(w * 1.2, h * 0.25);
        return [p.line([[port[0], 0], [x, 0]], { cls: 'glyph-port-line' }), ...p.hatch([x, -h * 0.9], [x, h * 0.9], depth, port[0] <= 0 ? -1 : 1, 6)];
    }
    return [p.line([[-w, 0], [-w * 0.3, 0]], { cls: 'glyph-port-line' }), ...p.hatch([-w * 0.3, -h * 0.8], [-w * 0.3, h * 0.8], w * 0.8, -1, 6)];
}

/** A disc seen from the side on its shaft, J on it; friction adds hatched ground below. */
export function inertia(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const friction = /Friction/.test(type);
    const dh = h * (friction ? 0.6 : 0.8);
    const cy = friction ? -h * 0.15 : 0;
    const dw = Math.min(w * 0.3, dh * 0.7);
    const gap = Math.max(1.2, dh * 0.08);
    const out: Glyph = [];
    for (const sgn of [-1, 1]) {
        // the shaft as a double line: a rotating mechanical connection
        const [a, b] = sgn < 0 ? [-w, -dw] : [dw, w];
        out.push(p.line([[a, cy - gap], [b, cy - gap]], { cls: 'glyph-shaft' }), p.line([[a, cy + gap], [b, cy + gap]], { cls: 'glyph-shaft' }));
    }
    out.push(p.rect(-dw, cy - dh, dw, cy + dh, { cls: 'glyph-disc', fill: '#fff' }), p.fitText('J', dh, dw * 0.8, dh * 0.5, [0, cy]));
    if (friction) out.push(...p.hatch([-w * 0.6, cy + dh + 1], [w * 0.6, cy + dh + 1], Math.max(1, (h - (cy + dh + 1)) * 0.9), -1, 6));
    if (/Gear/.test(type)) out.push(p.line([[-dw * 1.4, cy - dh * 0.6], [dw * 1.4, cy - dh * 0.6]], { dashed: true }), p.line([[-dw * 1.4, cy + dh * 0.6], [dw * 1.4, cy + dh * 0.6]], { dashed: true }));
    return out;
}

/** A coil on the shaft: a torsion spring, or the twist of a flexible shaft. */
export function torsionSpring(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const y = portsOf(type, w, h)[0]?.at[1] ?? 0;
    const cy = Math.abs(y) > h * 0.5 ? 0 : y;
    const a = Math.min(h * 0.6, w * 0.25);
    const loops = /RotShaft/.test(type) ? 5 : 3;
    const [x0, x1] = [-w * 0.6, w * 0.6];
    // a prolate cycloid: loops distinguish it from the zigzag of a translational spring
    const b = a * 0.8;
    const coil = p.curve((t) => {
        const th = t * loops * 2 * Math.PI;
        return [x0 + (x1 - x0) * t + b * (1 - Math.cos(th)), cy - a * Math.sin(th)];
    }, 16 * loops, { cls: 'glyph-spring' });
    const out: Glyph = [coil];
    // leads to the ports (Hopsan puts a torsion spring's ports on its bottom corners)
    for (const q of portsOf(type, w, h)) {
        const sx = Math.sign(q.at[0]);
        out.push(p.line([q.at, [sx * w * 0.6, q.at[1]], [sx * w * 0.6, cy]], { cls: 'glyph-port-line' }));
    }
    return out;
}

/** Two meshing gear wheels (pitch circles) on their shafts; a rack under the pinion for rack and pinion. */
export function gear(p: Pen, type: string): Glyph {
    const { w, h } = p;
    if (/RackAndPinion/.test(type)) {
        const r = Math.min(w, h) * 0.45;
        const out: Glyph = [p.circle([0, -r * 0.4], r, { cls: 'glyph-gear' }), p.circle([0, -r * 0.4], Math.max(1, r * 0.12), { filled: true })];
        const ry = -r * 0.4 + r + p.sw;
        out.push(p.line([[-w * 0.9, ry], [w * 0.9, ry]], { cls: 'glyph-rack' }));
        for (let i = -4; i <= 4; i++) out.push(p.line([[(i * w * 0.9) / 4.5, ry], [(i * w * 0.9) / 4.5, ry + Math.min(3, (h - ry) * 0.8)]], { cls: 'glyph-rack' }));
        return out;
    }
    // the pair centred in the box, touching at x = r1 - r2; shafts to the side ports
    const r1 = Math.min(h * 0.75, w * 0.55);
    const r2 = r1 * 0.6;
    const out: Glyph = [p.circle([-r2, 0], r1, { cls: 'glyph-gear' }), p.circle([r1, 0], r2, { cls: 'glyph-gear' }),
        p.circle([-r2, 0], Math.max(1, r1 * 0.12), { filled: true }), p.circle([r1, 0], Math.max(1, r2 * 0.15), { filled: true })];
    out.push(p.line([[-w, 0], [-r2 - r1, 0]], { cls: 'glyph-shaft' }), p.line([[r1 + r2, 0], [w, 0]], { cls: 'glyph-shaft' }));
    return out;
}

/** A pulley wheel with the rope over it. */
export function pulley(p: Pen): Glyph {
    const { w, h } = p;
    const r = Math.min(h * 0.6, w * 0.3);
    const rope: Pt[] = [[-w * 0.9, r], ...Pen.arc([0, 0], r, Math.PI / 2, Math.PI * 1.5, 10), [w * 0.9, -r]];
    return [p.circle([0, 0], r, { cls: 'glyph-gear' }), p.circle([0, 0], Math.max(1, r * 0.15), { filled: true }), p.line(rope, { cls: 'glyph-rope' })];
}

/** A lever on its fulcrum (triangle). */
export function lever(p: Pen): Glyph {
    const { w, h } = p;
    const long = h > w;
    const a: Pt = long ? [0, -h * 0.9] : [-w * 0.9, 0];
    const b: Pt = long ? [0, h * 0.9] : [w * 0.9, 0];
    const f = Math.min(w, h) * 0.5;
    const piv: Pt = long ? [0, h * 0.2] : [w * 0.2, 0];
    return [p.line([a, b], { cls: 'glyph-lever' }), p.poly(long ? [piv, [piv[0] + f, piv[1] - f * 0.6], [piv[0] + f, piv[1] + f * 0.6]] : [piv, [piv[0] - f * 0.6, piv[1] + f], [piv[0] + f * 0.6, piv[1] + f]])];
}

/**
 * Force, velocity, position and rotation sources (Hopsan's transformers turn a signal into one):
 * a circle with the quantity and an arrow to the power port.
 */
export function mechanicSource(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const port = portsOf(type, w, h).find((q) => /^P/.test(q.name))?.at ?? [w, 0];
    const r = p.u * 0.85;
    const letter = /Force/.test(type) ? 'F' : /Torque/.test(type) ? 'T' : /AngularVelocity/.test(type) ? 'ω' : /Theta/.test(type) ? 'φ' : /Velocity/.test(type) ? 'v' : 'x';
    const sx = Math.sign(port[0]) || 1;
    const cx = -sx * (w - r) * 0.5;
    return [p.circle([cx, 0], r, { cls: 'glyph-source' }), p.fitText(letter, r * 1.2, r * 0.6, r * 0.6, [cx, 0]),
        ...p.arrow([cx + sx * r, 0], [port[0], 0], 'glyph-source-arrow')];
}
