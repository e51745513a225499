// Logic gates in the distinctive shapes most engineers recognise (AND: a D, OR: a shield,
// XOR: a shield with a second back curve, NOT: a triangle with its bubble).
import { Pen, type Glyph, type Pt } from './draw';

export function gate(p: Pen, kind: 'and' | 'or' | 'xor' | 'not'): Glyph {
    const { w, h } = p;
    const gh = h * 0.7;
    const x0 = -Math.min(w * 0.6, gh * 1.1);
    const x1 = Math.min(w * 0.6, gh * 1.2);
    if (kind === 'not') {
        const r = Math.max(1.2, gh * 0.18);
        return [p.poly([[x0, -gh], [x1 - 2 * r, 0], [x0, gh]], { cls: 'glyph-gate' }), p.circle([x1 - r, 0], r, { cls: 'glyph-bubble' })];
    }
    if (kind === 'and') {
        const xm = x1 - gh;
        return [p.poly([[x0, -gh], [xm, -gh], ...Pen.arc([xm, 0], gh, -Math.PI / 2, Math.PI / 2, 14), [x0, gh]], { cls: 'glyph-gate' })];
    }
    // OR: concave back, two convex sides meeting at the output point
    const back = (t: number, dx = 0): Pt => [x0 + dx + (x1 - x0) * 0.22 * Math.sin(Math.PI * t), -gh + 2 * gh * t];
    const shield: Pt[] = [];
    for (let i = 0; i <= 10; i++) { const t = i / 10; shield.push([x0 + (x1 - x0) * t, -gh + gh * t * t]); }
    for (let i = 10; i >= 0; i--) { const t = i / 10; shield.push([x0 + (x1 - x0) * t, gh - gh * t * t]); }
    for (let i = 10; i >= 0; i--) shield.push(back(i / 10));
    const out: Glyph = [p.poly(shield, { cls: 'glyph-gate' })];
    if (kind === 'xor') out.push(p.curve((t) => back(t, -Math.min(3, (x0 + w) * 0.8)), 10, { cls: 'glyph-gate' }));
    return out;
}
