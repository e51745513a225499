// Electric symbols of our own: resistor (zigzag), capacitor (two plates), inductor (humps),
// sources (circle with + and −, or with an arrow), battery (long and short plates), ground,
// motor (circle with M on its shaft), switch, and the C/Q boundary sources of any domain.
import { Pen, portsOf, stubsToCircle, type Glyph, type Pt } from './draw';

/** The y of the side ports (Hopsan draws some two-poles off centre). */
function sidePortsY(type: string, w: number, h: number): number[] {
    return portsOf(type, w, h).filter((q) => /^P/.test(q.name) && Math.abs(Math.abs(q.at[0]) - w) < 1e-6).map((q) => q.at[1]);
}

export function resistor(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const y = sidePortsY(type, w, h)[0] ?? 0;
    const amp = Math.min(h * 0.7, h - Math.abs(y), w * 0.12);
    const out: Glyph = [p.line([[-w, y], [-w * 0.6, y]]), p.zigzag([-w * 0.6, y], [w * 0.6, y], amp, 6, 'glyph-resistor'), p.line([[w * 0.6, y], [w, y]])];
    if (/Var/.test(type)) out.push(...p.arrow([-w * 0.35, h * 0.9], [w * 0.35, -h * 0.9], 'glyph-adjust'));
    return out;
}

export function capacitor(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const y = sidePortsY(type, w, h)[0] ?? 0;
    const gap = Math.min(w * 0.12, h * 0.2);
    const plate = Math.min(h * 0.7, w * 0.6);
    // Hopsan's capacitor has its ports at the top corners: leads run down to the plates' middle
    const cy = Math.abs(y) > h * 0.5 ? 0 : y;
    return [p.line([[-w, y], [-w * 0.8, y], [-w * 0.8, cy], [-gap, cy]]), p.line([[-gap, cy - plate], [-gap, cy + plate]], { cls: 'glyph-plate' }),
        p.line([[gap, cy - plate], [gap, cy + plate]], { cls: 'glyph-plate' }), p.line([[gap, cy], [w * 0.8, cy], [w * 0.8, y], [w, y]])];
}

export function inductor(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const y = sidePortsY(type, w, h)[0] ?? 0;
    const n = 4;
    const r = Math.min((w * 1.4) / (2 * n), h + y > 0 ? (h + y) * 0.9 : h, w);
    const pts: Pt[] = [[-w, y]];
    for (let i = 0; i < n; i++) pts.push(...Pen.arc([-w * 0.7 + r + 2 * r * i, y], r, Math.PI, 2 * Math.PI, 8));
    pts.push([w, y]);
    return [p.line(pts, { cls: 'glyph-coil' })];
}

/** A circle on the vertical through its ports: + and − for voltage, an arrow for current. */
export function source(p: Pen, kind: 'voltage' | 'current'): Glyph {
    const { w, h } = p;
    const r = Math.min(w * 0.8, h * 0.6);
    const c: Pt = [0, 0];
    const out: Glyph = [p.circle(c, r, { cls: 'glyph-source' }), p.line([[0, -h], [0, -r]]), p.line([[0, r], [0, h * 0.9]])];
    if (kind === 'voltage') {
        const t = r * 0.22;
        out.push(p.line([[-t, -r * 0.45], [t, -r * 0.45]]), p.line([[0, -r * 0.45 - t], [0, -r * 0.45 + t]]), p.line([[-t, r * 0.45], [t, r * 0.45]]));
    } else {
        out.push(...p.arrow([0, r * 0.6], [0, -r * 0.6], 'glyph-source-arrow'));
    }
    return out;
}

/** Cells: long (+) and short (−) plates in pairs, the lead to the port on top. */
export function battery(p: Pen): Glyph {
    const { w, h } = p;
    const out: Glyph = [p.line([[0, -h], [0, -h * 0.45]])];
    for (let i = 0; i < 2; i++) {
        const y = -h * 0.45 + i * h * 0.45;
        out.push(p.line([[-w * 0.7, y], [w * 0.7, y]], { cls: 'glyph-plate' }), p.line([[-w * 0.35, y + h * 0.2], [w * 0.35, y + h * 0.2]], { cls: 'glyph-plate' }));
    }
    out.push(p.line([[0, h * 0.2], [0, h * 0.8]]), p.line([[-w * 0.4, h * 0.8], [w * 0.4, h * 0.8]]));
    return out;
}

/** Ground: the lead from the port on top onto three shortening bars. */
export function ground(p: Pen): Glyph {
    const { w, h } = p;
    return [p.line([[0, -h], [0, -h * 0.1]]), p.line([[-w * 0.8, -h * 0.1], [w * 0.8, -h * 0.1]]),
        p.line([[-w * 0.5, h * 0.3], [w * 0.5, h * 0.3]]), p.line([[-w * 0.2, h * 0.7], [w * 0.2, h * 0.7]])];
}

/** A motor: a circle with M, the electric leads to its ports and the shaft (double line) to the side. */
export function motor(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const ports = portsOf(type, w, h);
    const el = ports.filter((q) => /^Pel/.test(q.name)).map((q) => q.at);
    const cx = el.length ? el.reduce((sum, q) => sum + q[0], 0) / el.length : 0;
    const r = Math.min(h * 0.55, (w - Math.abs(cx)) * 0.7, w * 0.7);
    const c: Pt = [cx, 0];
    const out: Glyph = [p.circle(c, r, { cls: 'glyph-machine' }), p.fitText('M', r * 1.1, r * 0.6, r * 0.5, c), ...stubsToCircle(p, el, c, r)];
    const shaft = ports.find((q) => /^Pm/.test(q.name))?.at ?? [w, 0];
    const sx = Math.sign(shaft[0]) || 1;
    const gap = Math.max(1.2, r * 0.07);
    out.push(p.line([[cx + sx * r, shaft[1] - gap], [sx * w, shaft[1] - gap]], { cls: 'glyph-shaft' }), p.line([[cx + sx * r, shaft[1] + gap], [sx * w, shaft[1] + gap]], { cls: 'glyph-shaft' }));
    if (/Gear/.test(type)) {
        // the gear box on the shaft
        const gx = cx + sx * (r + (w - Math.abs(cx) - r) * 0.5);
        const g = Math.min(r * 0.5, (w - Math.abs(cx) - r) * 0.3);
        if (g > 2) out.push(p.rect(gx - g, -g * 1.4, gx + g, g * 1.4, { cls: 'glyph-gear', fill: '#fff' }));
    }
    return out;
}

/** An open switch: two contacts, the blade lifted off the right one. */
export function electricSwitch(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const y = sidePortsY(type, w, h)[0] ?? 0;
    const d = Math.min(1.5, h * 0.2);
    return [p.line([[-w, y], [-w * 0.4, y]]), p.circle([-w * 0.4, y], d, { filled: true }), p.line([[-w * 0.4, y], [w * 0.35, -h * 0.9]], { cls: 'glyph-blade' }),
        p.circle([w * 0.4, y], d, { filled: true }), p.line([[w * 0.4, y], [w, y]])];
}

/** Hopsan's C- and Q-type boundary sources (any domain): a small circle with its letter. */
export function boundarySource(p: Pen, type: string): Glyph {
    const r = p.u * 0.9;
    return [p.circle([0, 0], r, { cls: 'glyph-source' }), p.fitText(/CSource/.test(type) ? 'C' : 'Q', r * 1.3, r * 0.7, r * 0.7)];
}
