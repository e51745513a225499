// Sensors of every domain as one gauge: a circle with a pointer and the measured quantity's
// letter, joined to the measured port. Sources draw a triangle or arrow instead of the pointer,
// so the two never look alike.
import { Pen, portsOf, stubsToCircle, type Glyph, type Pt } from './draw';

/** The measured quantity's symbol, from the sensor's type name. */
export function quantity(type: string): string {
    const t = type.replace(/^(Hydraulic|Mechanic|Electric|Pneumatic)/, '');
    const table: [RegExp, string][] = [
        [/^DifferentialPressure/, 'Δp'], [/^Pressure|^Psensor/, 'p'], [/^Flow|^Qm/, 'q'], [/^Power|^dE/, 'P'], [/^Node/, '•'],
        [/^Angle/, 'φ'], [/^AngularVelocity/, 'ω'], [/^Position/, 'x'], [/^Speed/, 'v'], [/^Force/, 'F'], [/^Torque/, 'T'],
        [/^Tsensor/, 'T'], [/^Isensor/, 'I'], [/^Usensor/, 'U'],
    ];
    return table.find(([re]) => re.test(t))?.[1] ?? '';
}

export function sensor(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const r = p.u * 0.72;
    const c: Pt = [0, 0];
    const ports = portsOf(type, w, h).filter((q) => /^P/.test(q.name) && Math.abs(Math.abs(q.at[1]) - h) < 1e-6).map((q) => q.at);
    const out: Glyph = [p.circle(c, r, { cls: 'glyph-gauge', fill: '#fff' }), ...stubsToCircle(p, ports, c, r)];
    // a scale on the upper half and the pointer across it
    out.push(p.line(Pen.arc(c, r * 0.78, Math.PI * 1.15, Math.PI * 1.85, 8), { cls: 'glyph-scale' }));
    out.push(...p.arrow([-r * 0.25, r * 0.25], [r * 0.5, -r * 0.5], 'glyph-pointer'));
    out.push(p.circle(c, Math.max(0.8, r * 0.08), { filled: true }));
    const q = quantity(type);
    if (q) out.push(p.fitText(q, r * 0.75, r * 0.5, r * 0.3, [0, r * 0.5]));
    return out;
}
