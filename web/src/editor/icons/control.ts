// Controllers: PID blocks by their name, the attitude controllers as an artificial horizon with
// the aircraft on it, and the electric controllers as the circuit element they act as (a
// controlled current source; a chopper switch with its pulse train).
import { Pen, portsOf, type Glyph, type Pt } from './draw';

/** PID and PI-lead controllers: the letters, and the step response they aim for beneath. */
export function pid(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const label = /PIlead/.test(type) ? 'PI-lead' : 'PID';
    const [x0, x1, y0, y1] = [-w * 0.55, w * 0.55, h * 0.75, h * 0.15];
    return [
        p.fitText(label, h * 0.8, w * 0.75, h * 0.3, [0, -h * 0.4]),
        p.curve((t) => [x0 + (x1 - x0) * t, y0 + (y1 - y0) * (1 - Math.exp(-6 * t) * Math.cos(9 * t))], 20, { cls: 'glyph-wave' }),
        p.line([[x0, y1], [x1, y1]], { faint: true, dashed: true }),
    ];
}

/** An artificial horizon: the dial, the tilted horizon across it and the fixed aircraft mark. */
export function attitudeControl(p: Pen): Glyph {
    const r = p.u * 0.62;
    const tilt = 0.4;
    const [c, s] = [Math.cos(tilt) * r, Math.sin(tilt) * r];
    // the ground: the part of the dial below the tilted horizon, shaded
    const ground = Pen.arc([0, 0], r, -tilt, Math.PI - tilt, 16);
    return [
        p.circle([0, 0], r, { cls: 'glyph-dial', fill: '#fff' }),
        p.poly(ground, { cls: 'glyph-ground', fill: '#e6dccb' }),
        p.line([[-c, s], [c, -s]], { cls: 'glyph-horizon' }),
        p.line([[-r * 0.6, 0], [-r * 0.2, 0], [0, r * 0.2], [r * 0.2, 0], [r * 0.6, 0]], { cls: 'glyph-aircraft' }),
        p.circle([0, 0], Math.max(0.8, r * 0.07), { filled: true }),
    ];
}

/** The line between the two electric ports, at their height, broken for the element in the middle. */
function throughLine(p: Pen, type: string, gap: number): { y: number; out: Glyph } {
    const ports = portsOf(type, p.w, p.h).filter((q) => /^Pel/.test(q.name)).map((q) => q.at);
    const y = ports[0]?.[1] ?? 0;
    return { y, out: [p.line([[-p.w, y], [-gap, y]], { cls: 'glyph-port-line' }), p.line([[gap, y], [p.w, y]], { cls: 'glyph-port-line' })] };
}

/** Current controller: a controlled current source (diamond with its arrow), its reference from above. */
export function currentController(p: Pen, type: string): Glyph {
    const r = Math.min(p.h * 0.45, p.w * 0.3);
    const { y, out } = throughLine(p, type, r);
    out.push(p.poly([[-r, y], [0, y - r], [r, y], [0, y + r]], { cls: 'glyph-diamond', fill: '#fff' }), ...p.arrow([-r * 0.55, y], [r * 0.6, y], 'glyph-arrow'));
    out.push(...p.arrow([0, -p.h], [0, y - r], 'glyph-reference'));
    return out;
}

/** PWM converter: a switch between the ports, the pulse train that drives it below. */
export function pwm(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const gap = w * 0.3;
    const { y, out } = throughLine(p, type, gap);
    out.push(p.line([[-gap, y], [gap * 0.8, y - h * 0.3]], { cls: 'glyph-switch' }), p.circle([gap, y], Math.max(0.8, p.sw), { filled: true }));
    const [b0, b1] = [h * 0.8, h * 0.35];
    const train: Pt[] = [[-w * 0.7, b0]];
    for (let i = 0; i < 3; i++) {
        const x = -w * 0.7 + (i * w * 1.4) / 3;
        train.push([x, b1], [x + w * 0.25, b1], [x + w * 0.25, b0], [x + (w * 1.4) / 3, b0]);
    }
    out.push(p.line(train, { cls: 'glyph-wave' }));
    return out;
}
