// Animation widgets as the control or instrument they show: a dial gauge, a lamp (the circuit
// symbol), a slider on its track, a toggle switch (a push button for the momentary one), a
// numeric display and an input field with its caret.
import { Pen, type Glyph, type Pt } from './draw';

export function dialGauge(p: Pen): Glyph {
    const r = p.u * 0.8;
    const c: Pt = [0, r * 0.15];
    const [a0, a1] = [Math.PI * 0.8, Math.PI * 2.2];
    const out: Glyph = [p.line(Pen.arc(c, r, a0, a1, 24), { cls: 'glyph-dial' })];
    for (let i = 0; i <= 6; i++) {
        const a = a0 + ((a1 - a0) * i) / 6;
        out.push(p.line([[c[0] + r * 0.8 * Math.cos(a), c[1] + r * 0.8 * Math.sin(a)], [c[0] + r * Math.cos(a), c[1] + r * Math.sin(a)]], { cls: 'glyph-tick' }));
    }
    out.push(...p.arrow(c, [c[0] + r * 0.65 * Math.cos(Math.PI * 1.7), c[1] + r * 0.65 * Math.sin(Math.PI * 1.7)], 'glyph-pointer'), p.circle(c, Math.max(0.8, r * 0.07), { filled: true }));
    return out;
}

export function lamp(p: Pen): Glyph {
    const r = p.u * 0.65;
    const k = r * Math.SQRT1_2;
    return [p.circle([0, 0], r, { cls: 'glyph-lamp', fill: '#fff' }), p.line([[-k, -k], [k, k]], { cls: 'glyph-lamp' }), p.line([[-k, k], [k, -k]], { cls: 'glyph-lamp' })];
}

/** A slider along the long side of its box, the knob part way. */
export function slider(p: Pen): Glyph {
    const along = p.h >= p.w ? p : p.transposed();
    const { w, h } = along;
    return [
        along.line([[0, -h * 0.85], [0, h * 0.85]], { cls: 'glyph-track' }),
        along.rect(-w * 0.55, -h * 0.05, w * 0.55, h * 0.12, { cls: 'glyph-knob', fill: '#fff' }),
    ];
}

export function toggle(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const [hw, hh] = [Math.min(w * 0.7, h * 1.4), h * 0.5];
    if (/Momentary/.test(type)) {
        return [p.line([[-hw, hh], [hw, hh]], { cls: 'glyph-base' }), p.rect(-hw * 0.45, -hh * 0.2, hw * 0.45, hh, { cls: 'glyph-button', fill: '#fff' }), p.line([[0, -hh * 0.2], [0, -hh * 1.4]], { cls: 'glyph-stem' })];
    }
    return [p.roundedRect(-hw, -hh, hw, hh, hh, { cls: 'glyph-toggle', fill: '#fff' }), p.circle([hw - hh, 0], hh * 0.7, { filled: true })];
}

/** A display: a screen with a number on it. */
export function display(p: Pen): Glyph {
    const { w, h } = p;
    return [p.rect(-w * 0.85, -h * 0.65, w * 0.85, h * 0.65, { cls: 'glyph-screen' }), p.fitText('0.00', h, w * 0.7, h * 0.45)];
}

/** An input field: a box with a number and the text caret after it. */
export function numericInput(p: Pen): Glyph {
    const { w, h } = p;
    const tw = Math.min(w * 0.4, h * 1.2);
    return [p.rect(-w * 0.85, -h * 0.6, w * 0.85, h * 0.6, { cls: 'glyph-field', fill: '#fff' }), p.fitText('123', h * 0.9, tw * 0.5, h * 0.4, [-w * 0.85 + tw * 0.5 + w * 0.05, 0]),
        p.line([[-w * 0.8 + tw + w * 0.04, -h * 0.4], [-w * 0.8 + tw + w * 0.04, h * 0.4]], { cls: 'glyph-caret' })];
}
