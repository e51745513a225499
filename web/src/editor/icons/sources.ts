// Signal sources as the curve they put out over time (step, sine, ramp, pulse, square wave,
// noise, staircase), the constant as its symbol, time as a clock, and sinks as a scope screen.
import { Pen, type Glyph, type Pt } from './draw';

/** The waveform of a source, in its box: time to the right, value upwards. */
export function waveform(p: Pen, kind: 'step' | 'sine' | 'ramp' | 'pulse' | 'square' | 'noise' | 'staircase', type = ''): Glyph {
    const a = Math.min(p.w, p.h * 1.3) * 0.75;
    const b = p.h * 0.55;
    let pts: Pt[];
    switch (kind) {
        case 'step':
            if (/Soft|Exponential/.test(type)) return [p.curve((t) => [-a + 2 * a * t, t < 0.3 ? b : b - 2 * b * (1 - Math.exp(-(t - 0.3) * 8))], 20, { cls: 'glyph-wave' })];
            pts = [[-a, b], [-a * 0.2, b], [-a * 0.2, -b], [a, -b]];
            break;
        case 'sine':
            return [p.curve((t) => [-a + 2 * a * t, -b * Math.sin(t * 2 * Math.PI)], 24, { cls: 'glyph-wave' })];
        case 'ramp':
            pts = [[-a, b], [-a * 0.4, b], [a * 0.5, -b], [a, -b]];
            break;
        case 'pulse':
            pts = [[-a, b], [-a * 0.35, b], [-a * 0.35, -b], [a * 0.25, -b], [a * 0.25, b], [a, b]];
            break;
        case 'square':
            pts = [[-a, b], [-a, -b], [-a * 0.5, -b], [-a * 0.5, b], [0, b], [0, -b], [a * 0.5, -b], [a * 0.5, b], [a, b]];
            break;
        case 'staircase':
            pts = [[-a, b], [-a * 0.5, b], [-a * 0.5, b * 0.33], [0, b * 0.33], [0, -b * 0.33], [a * 0.5, -b * 0.33], [a * 0.5, -b], [a, -b]];
            break;
        default: {
            // noise: a fixed irregular trace (no randomness: the drawing stays the same)
            const ys = [0.1, -0.6, 0.4, -0.2, 0.9, -0.8, 0.3, 0.6, -0.5, 0.2, -0.9, 0.5, -0.1];
            pts = ys.map((y, i) => [-a + (2 * a * i) / (ys.length - 1), y * b]);
        }
    }
    return [p.line(pts, { cls: 'glyph-wave' })];
}

/** A constant: its letter, as the value is shown in the block of a block diagram. */
export function constant(p: Pen): Glyph {
    return [p.fitText('C', p.h * 1.1, p.w * 0.7, p.h * 0.6)];
}

/** Simulation time (and time step): a clock face with two hands. */
export function clock(p: Pen, type: string): Glyph {
    const r = p.u * 0.72;
    const out: Glyph = [p.circle([0, 0], r, { cls: 'glyph-clock' }), p.line([[0, -r * 0.7], [0, 0], [r * 0.5, 0]], { cls: 'glyph-hands' })];
    for (let i = 0; i < 4; i++) {
        const a = (i * Math.PI) / 2;
        out.push(p.line([[Math.cos(a) * r * 0.8, Math.sin(a) * r * 0.8], [Math.cos(a) * r, Math.sin(a) * r]]));
    }
    if (/step/.test(type)) out.push(p.fitText('Δt', r * 0.5, r * 0.3, r * 0.2, [-r * 0.35, r * 0.45]));
    return out;
}

/** A sink (scope, logger): a screen with a trace on it. */
export function sink(p: Pen): Glyph {
    const { w, h } = p;
    const [sw, sh] = [Math.min(w * 0.75, h * 1.3), h * 0.65];
    const out: Glyph = [p.rect(-sw, -sh, sw, sh, { cls: 'glyph-screen', fill: '#fff' }),
        p.curve((t) => [-sw * 0.8 + 1.6 * sw * t, sh * 0.1 - sh * 0.55 * Math.sin(t * 1.6 * Math.PI) * (1 - t * 0.4)], 20, { cls: 'glyph-wave' })];
    return out;
}
