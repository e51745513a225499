// Fluid-power valve symbols of our own, in the component's frame (centre 0,0; box ±w,±h):
// directional valves as a row of envelopes with flow arrows, pressure valves as one envelope
// with an offset arrow, a spring and a dashed pilot line, check valves as a ball on a seat.
import { s } from '../ui/dom';

type Pt = [number, number];
const stroke = { fill: 'none', stroke: 'currentColor', 'stroke-width': 1.2, 'stroke-linejoin': 'round', 'stroke-linecap': 'round' };

function path(cls: string, points: Pt[], dashed = false): SVGPolylineElement {
    return s('polyline', { ...stroke, class: cls, points: points.map((p) => p.join(',')).join(' '), ...(dashed ? { 'stroke-dasharray': '3 2' } : {}) });
}

/** A flow arrow from a to b with a filled head at b. */
function arrow(a: Pt, b: Pt): SVGElement[] {
    const len = Math.hypot(b[0] - a[0], b[1] - a[1]) || 1;
    const [ux, uy] = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
    const head = Math.min(5, len * 0.35);
    const base: Pt = [b[0] - ux * head, b[1] - uy * head];
    const wing = head * 0.5;
    return [path('glyph-arrow', [a, base]),
        s('polygon', { class: 'glyph-arrow', fill: 'currentColor', points: `${b.join(',')} ${base[0] - uy * wing},${base[1] + ux * wing} ${base[0] + uy * wing},${base[1] - ux * wing}` })];
}

function envelope(x: number, y: number, width: number, height: number): SVGElement {
    return s('rect', { ...stroke, class: 'glyph-envelope', x, y, width, height });
}

function spring(x0: number, x1: number, amp: number): SVGElement {
    const pts: Pt[] = [[x0, 0]];
    const n = 5;
    for (let i = 1; i <= n; i++) pts.push([x0 + ((x1 - x0) * i) / (n + 1), i % 2 ? -amp : amp]);
    pts.push([x1, 0]);
    return path('glyph-spring', pts);
}

/** Envelopes in a row: crossed flow, closed centre (three positions), parallel flow. */
function directional(type: string, w: number, h: number): SVGElement[] {
    // Hopsan names them ports-then-positions (Hydraulic43Valve: 4 ports, 3 positions)
    const digits = /(\d)(\d)/.exec(type);
    const n = Math.max(2, Math.min(3, digits ? Number(digits[2]) : 2));
    const cw = Math.min((2 * w * 0.9) / n, 2 * h * 0.9 * 1.4);
    const ch = Math.min(2 * h * 0.8, cw);
    const x0 = (-n * cw) / 2;
    const [top, bottom] = [-ch / 2, ch / 2];
    const out: SVGElement[] = [];
    for (let i = 0; i < n; i++) {
        const left = x0 + i * cw;
        out.push(envelope(left, top, cw, ch));
        const [a, b] = [left + cw * 0.3, left + cw * 0.7];
        if (n === 3 && i === 1) {
            // closed centre: blocked ports drawn as short T bars
            out.push(path('glyph-block', [[a, bottom], [a, bottom - ch * 0.3]]), path('glyph-block', [[a - 3, bottom - ch * 0.3], [a + 3, bottom - ch * 0.3]]));
            out.push(path('glyph-block', [[b, top], [b, top + ch * 0.3]]), path('glyph-block', [[b - 3, top + ch * 0.3], [b + 3, top + ch * 0.3]]));
        } else if (i === 0) {
            out.push(...arrow([a, bottom - 2], [b, top + 2]), ...arrow([b, bottom - 2], [a, top + 2]));
        } else {
            out.push(...arrow([a, bottom - 2], [a, top + 2]), ...arrow([b, top + 2], [b, bottom - 2]));
        }
    }
    return out;
}

/** One envelope, the arrow offset from the ports' line, a spring on the right, pilot on the left. */
function pressureValve(w: number, h: number): SVGElement[] {
    const side = Math.min(2 * h * 0.8, w * 0.9);
    const [x, y] = [-side / 2, -side / 2];
    return [envelope(x, y, side, side), ...arrow([x + side * 0.35, y + side - 2], [x + side * 0.35, y + 2]),
        spring(x + side, Math.min(w * 0.95, x + side * 2), side * 0.2),
        path('glyph-pilot', [[0, y + side], [0, y + side + 3], [x - 4, y + side + 3], [x - 4, 0], [x, 0]], true)];
}

/** A ball on a V seat; pilot-operated ones get a pilot line, pre-loaded ones a spring. */
function checkValve(type: string, w: number, h: number): SVGElement[] {
    const r = Math.min(w, h) * 0.35;
    const out: SVGElement[] = [s('circle', { ...stroke, class: 'glyph-ball', cx: -r * 0.2, cy: 0, r }),
        path('glyph-seat', [[r * 0.6, -r * 1.4], [-r * 0.2 + r * 1.1, 0], [r * 0.6, r * 1.4]])];
    if (/Pilot/.test(type)) out.push(path('glyph-pilot', [[0, h * 0.95], [0, r * 1.1]], true));
    if (/PreLoaded/.test(type)) out.push(spring(-w * 0.9, -r * 1.2, r * 0.5));
    return out;
}

/** The valve symbol for a valve type, or null for types that are no valve. */
export function valveGlyph(type: string, w: number, h: number): SVGElement[] | null {
    if (!/Valve/.test(type) || /ValvePlate/.test(type)) return null;
    if (/CheckValve/.test(type) && !/Directional|Orifice/.test(type)) return checkValve(type, w, h);
    if (/Pressure(Relief|Reducing|Control|Compensating|Drop)|CounterBalance|OverCenter/.test(type)) return pressureValve(w, h);
    return directional(type, w, h);
}
