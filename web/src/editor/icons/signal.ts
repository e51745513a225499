// Block-diagram symbols of our own for signal blocks: gain triangle, summing circle with its
// sign, integrator and transfer functions as fractions in s, delays, filters as their
// magnitude curve, non-linear characteristics on small axes, lookup tables and math functions.
import { Pen, type Glyph, type Pt } from './draw';

export function gain(p: Pen): Glyph {
    const { w, h } = p;
    const [x0, x1, y] = [-w * 0.7, w * 0.75, h * 0.72];
    return [p.poly([[x0, -y], [x1, 0], [x0, y]], { cls: 'glyph-gain' }), p.fitText('K', y * 0.9, (x1 - x0) * 0.2, y * 0.4, [x0 + (x1 - x0) * 0.33, 0])];
}

/**
 * A summing circle with the sign of the operation (+, −, Σ), products with × and ÷. Signs are
 * drawn as strokes, not text: they stay crisp and centred at any size.
 */
export function operatorCircle(p: Pen, type: string): Glyph {
    const r = p.u * 0.72;
    const a = r * 0.45;
    const out: Glyph = [p.circle([0, 0], r, { cls: 'glyph-sum' })];
    if (/Sum/.test(type)) out.push(p.fitText('Σ', r * 1.2, r * 0.6, r * 0.55));
    else if (/Multiply/.test(type)) out.push(p.line([[-a * 0.75, -a * 0.75], [a * 0.75, a * 0.75]], { cls: 'glyph-sign' }), p.line([[-a * 0.75, a * 0.75], [a * 0.75, -a * 0.75]], { cls: 'glyph-sign' }));
    else if (/Divide/.test(type)) out.push(p.line([[-a, 0], [a, 0]], { cls: 'glyph-sign' }), p.circle([0, -a * 0.6], Math.max(0.6, r * 0.07), { filled: true }), p.circle([0, a * 0.6], Math.max(0.6, r * 0.07), { filled: true }));
    else {
        out.push(p.line([[-a, 0], [a, 0]], { cls: 'glyph-sign' }));
        if (!/Sub/.test(type)) out.push(p.line([[0, -a], [0, a]], { cls: 'glyph-sign' }));
    }
    return out;
}

/** A fraction: numerator over a bar over denominator (1/s, b(s)/a(s)). */
function fraction(p: Pen, num: string, den: string): Glyph {
    const { w, h } = p;
    const bar = Math.min(w * 0.75, Math.max(num.length, den.length) * h * 0.3);
    const hh = h * 0.34;
    return [p.fitText(num, h * 0.6, w * 0.8, hh, [0, -h * 0.42]), p.line([[-bar, 0], [bar, 0]], { cls: 'glyph-fraction' }), p.fitText(den, h * 0.6, w * 0.8, hh, [0, h * 0.42])];
}

export const integrator = (p: Pen): Glyph => fraction(p, '1', 's');

export function transferFunction(p: Pen, type: string): Glyph {
    return /Filter/.test(type) && !/Order/.test(type) ? fraction(p, '1', 'a(s)') : fraction(p, 'b(s)', 'a(s)');
}

/** z⁻¹ for one time step, else a pulse and its copy shifted later on the time axis. */
export function delay(p: Pen, type: string): Glyph {
    const { w, h } = p;
    if (/Unit/.test(type)) return [p.fitText('z⁻¹', h, w * 0.8, h * 0.6)];
    const [x0, y0, y1] = [-w * 0.8, h * 0.5, -h * 0.4];
    const pw = w * 0.35;
    return [p.line([[x0, y0], [x0 + pw * 0.3, y0], [x0 + pw * 0.3, y1], [x0 + pw, y1], [x0 + pw, y0], [w * 0.8, y0]], { cls: 'glyph-wave', dashed: true }),
        p.line([[x0 + pw * 1.8, y0], [x0 + pw * 1.8, y1], [x0 + pw * 2.5, y1], [x0 + pw * 2.5, y0]], { cls: 'glyph-wave' }),
        ...p.arrow([x0 + pw * 0.7, y1 - h * 0.25], [x0 + pw * 2.1, y1 - h * 0.25], 'glyph-arrow')];
}

/** Low- and high-pass filters: their magnitude over frequency, flat then falling (or rising). */
export function filter(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const steep = /2Filter/.test(type) ? 1.6 : 0.9;
    const [x0, x1, top] = [-w * 0.8, w * 0.8, -h * 0.4];
    const knee = 0;
    const fall = Math.min(h * 0.75, (x1 - knee) * 0.5 * steep);
    const curve: Pt[] = /LP/.test(type) ? [[x0, top], [knee, top], [x1, top + fall]] : [[x0, top + fall], [-knee, top], [x1, top]];
    // on faint axes, so it reads as a plot (gain over frequency), not as a switch
    return [p.line([[x0, -h * 0.75], [x0, h * 0.7], [x1, h * 0.7]], { cls: 'glyph-axis', faint: true }), p.line(curve, { cls: 'glyph-wave' })];
}

/** Small axes through the centre, behind a characteristic curve. */
function axes(p: Pen): Glyph {
    const { w, h } = p;
    return [p.line([[-w * 0.8, 0], [w * 0.8, 0]], { cls: 'glyph-axis', faint: true }), p.line([[0, -h * 0.8], [0, h * 0.8]], { cls: 'glyph-axis', faint: true })];
}

export function saturation(p: Pen): Glyph {
    const [a, b] = [Math.min(p.w * 0.7, p.h * 1.2), p.h * 0.6];
    return [...axes(p), p.line([[-a, b], [-b * 0.7, b], [b * 0.7, -b], [a, -b]], { cls: 'glyph-wave' })];
}

/** Dead zone, hysteresis, rate limiter, sign and absolute value as their input-output curves. */
export function characteristic(p: Pen, type: string): Glyph {
    const [a, b] = [Math.min(p.w * 0.75, p.h * 1.2), p.h * 0.6];
    const c = b * 0.5;
    const curves: Record<string, Pt[]> = {
        DeadZone: [[-a, b], [-c, 0], [c, 0], [a, -b]],
        Hysteresis: [[-a, b * 0.8], [c, b * 0.8], [c, -b * 0.8], [a, -b * 0.8], [-c, -b * 0.8], [-c, b * 0.8]],
        RateLimiter: [[-a, b], [-a * 0.2, b], [a * 0.6, -b], [a, -b]],
        Sign: [[-a, b * 0.7], [0, b * 0.7], [0, -b * 0.7], [a, -b * 0.7]],
        AbsoluteValue: [[-a * 0.8, -b], [0, b * 0.8], [a * 0.8, -b]],
    };
    const key = Object.keys(curves).find((k) => type.endsWith(k)) ?? 'DeadZone';
    const out: Glyph = [...axes(p), p.line(curves[key], { cls: 'glyph-wave' })];
    if (key === 'RateLimiter') out.unshift(p.line([[-a, b], [-a * 0.2, b], [-a * 0.2, -b], [a, -b]], { cls: 'glyph-axis', dashed: true, faint: true }));
    return out;
}

/** A table: a grid with its header row and column, the curve it interpolates across it. */
export function lookupTable(p: Pen): Glyph {
    const { w, h } = p;
    const [x0, x1, y0, y1] = [-Math.min(w * 0.8, h * 1.4), Math.min(w * 0.8, h * 1.4), -h * 0.7, h * 0.7];
    const out: Glyph = [p.rect(x0, y0, x1, y1, { cls: 'glyph-table' })];
    for (let i = 1; i < 3; i++) out.push(p.line([[x0 + ((x1 - x0) * i) / 3, y0], [x0 + ((x1 - x0) * i) / 3, y1]], { cls: 'glyph-table' }));
    out.push(p.line([[x0, 0], [x1, 0]], { cls: 'glyph-table' }));
    return out;
}

const functionLabels: Record<string, string> = {
    Sin: 'sin', Cos: 'cos', Tan: 'tan', Asin: 'asin', Acos: 'acos', Atan: 'atan', Atan2: 'atan2', Sinh: 'sinh', Cosh: 'cosh', Tanh: 'tanh',
    Exp: 'eˣ', Log: 'ln', Log10: 'lg', Sqrt: '√x', Power: 'xʸ', Square: 'x²', Floor: '⌊x⌋', Ceil: '⌈x⌉', Round: 'rnd',
    Min: 'min', Max: 'max', SampleAndHold: 'S/H',
};

/** Math functions by their usual name in the block. */
export function mathFunction(p: Pen, type: string): Glyph {
    const label = functionLabels[type.replace(/^Signal/, '')] ?? type.replace(/^Signal/, '').toLowerCase();
    return [p.fitText(label, p.h * 0.8, p.w * 0.85, p.h * 0.55)];
}

/** > or < between the inputs. */
export function comparator(p: Pen, type: string): Glyph {
    return [p.fitText(/Greater/.test(type) ? '>' : '<', p.h * 1.2, p.w * 0.7, p.h * 0.7)];
}

/** A latch: its inputs (S R or J K) on the left, Q on the right. */
export function latch(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const [a, b] = /JK/.test(type) ? ['J', 'K'] : ['S', 'R'];
    const size = Math.min(h * 0.35, w * 0.45);
    return [p.fitText(a, size, w * 0.25, h * 0.2, [-w * 0.55, -h * 0.45]), p.fitText(b, size, w * 0.25, h * 0.2, [-w * 0.55, h * 0.45]),
        p.fitText('Q', size, w * 0.25, h * 0.2, [w * 0.55, -h * 0.45]), p.line([[0, -h * 0.85], [0, h * 0.85]], { cls: 'glyph-axis', faint: true })];
}
