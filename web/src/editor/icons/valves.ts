// Fluid-power valve symbols of our own (ISO 1219 style): directional valves as a row of
// envelopes with flow arrows between an actuator and a return spring, pressure valves as one
// envelope with an arrow, a spring and a dashed pilot line, check valves as a ball on a seat.
import { Pen, edgePorts, type Glyph } from './draw';

const envelope = (p: Pen, x: number, y: number, w: number, h: number) => p.rect(x, y, x + w, y + h, { cls: 'glyph-envelope' });

/** Positions: Hopsan names valves ports-then-positions (Hydraulic43Valve: 4 ports, 3 positions). */
function positions(type: string): number {
    const digits = /(\d)(\d)/.exec(type);
    return Math.max(2, Math.min(3, digits ? Number(digits[2]) : 2));
}

/**
 * Envelopes in a row (crossed flow, closed centre, parallel flow), lines from the box edges
 * to the envelope the ports are drawn at (the centre one, or the right one of two), a spring on
 * the right and on the left the actuator: a dashed pilot for pressure-controlled valves, else a
 * solenoid. Servo (flow control) valves get the two lines of continuously variable positions.
 * The envelopes are placed so that their flow paths continue Hopsan's port lines.
 */
export function directionalValve(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const n = positions(type);
    const twoPort = /^Hydraulic22|PressureControlled22/.test(type);
    const ports = edgePorts(type, w, h);
    const xs = [...new Set(ports.map((q) => Math.round(q[0] * 100) / 100))].sort((a, b) => a - b);
    // the ports' envelope and where its two flow paths run (fractions of its width)
    const k = n === 3 ? 1 : n - 1;
    const span = xs.length > 1 ? xs[xs.length - 1] - xs[0] : 0;
    let cw = span > 0 ? span / 0.6 : Math.min((2 * w * 0.72) / n, 2 * h * 0.75 * 1.4);
    const mid = xs.length ? (xs[0] + xs[xs.length - 1]) / 2 : 0;
    let x0 = mid - cw * (k + 0.5);
    // keep the row (and some room for spring and actuator) inside the box
    const room = w * 0.97;
    if (x0 < -room + cw * 0.3 || x0 + n * cw > room - cw * 0.3) {
        // narrower envelopes, the ports' one still on the ports; shifted only if that gets too narrow
        cw = Math.min(cw, (room - mid) / (n - k - 0.2), (room + mid) / (k + 0.8));
        cw = Math.max(cw, Math.min((2 * room) / (n + 0.6), 2 * h * 0.5));
        x0 = Math.max(-room + cw * 0.3, Math.min(mid - cw * (k + 0.5), room - cw * 0.3 - n * cw));
    }
    const ch = Math.min(2 * h * 0.62, cw);
    const [top, bottom] = [-ch / 2, ch / 2];
    const gap = Math.min(2, cw * 0.08);
    const [fa, fb] = span > 0 ? [0.2, 0.8] : [0.3, 0.7];
    const bar = Math.min(3, cw * 0.12);
    const block = (x: number, fromTop: boolean): Glyph => {
        const [y0, y1] = fromTop ? [top, top + ch * 0.3] : [bottom, bottom - ch * 0.3];
        return [p.line([[x, y0], [x, y1]], { cls: 'glyph-block' }), p.line([[x - bar, y1], [x + bar, y1]], { cls: 'glyph-block' })];
    };
    const out: Glyph = [];
    for (let i = 0; i < n; i++) {
        const left = x0 + i * cw;
        out.push(envelope(p, left, top, cw, ch));
        const [a, b] = [left + cw * fa, left + cw * fb];
        const c = left + cw / 2;
        if (twoPort) {
            // 2/2: one envelope passes the flow, the other blocks both ports
            if (i === k) out.push(...block(c, true), ...block(c, false));
            else out.push(...p.arrow([c, bottom - gap], [c, top + gap], 'glyph-arrow'));
        } else if (n === 3 && i === 1) {
            // closed centre: blocked ports drawn as short T bars
            out.push(...block(a, false), ...block(b, true));
        } else if (i === 0) {
            out.push(...p.arrow([a, bottom - gap], [b, top + gap], 'glyph-arrow'), ...p.arrow([b, bottom - gap], [a, top + gap], 'glyph-arrow'));
        } else {
            out.push(...p.arrow([a, bottom - gap], [a, top + gap], 'glyph-arrow'), ...p.arrow([b, top + gap], [b, bottom - gap], 'glyph-arrow'));
        }
    }
    const x1 = x0 + n * cw;
    for (const [x, y] of ports) {
        if (x > x0 && x < x1) out.push(p.line([[x, y], [x, y < 0 ? top : bottom]], { cls: 'glyph-port-line' }));
    }
    // return spring on the right
    const springEnd = Math.min(w * 0.98, x1 + cw * 0.7);
    if (springEnd - x1 > 3) out.push(p.zigzag([x1, 0], [springEnd, 0], ch * 0.25, 5, 'glyph-spring'));
    // actuator on the left
    const ax = Math.max(-w * 0.98, x0 - Math.min(cw * 0.35, ch * 0.6));
    if (/PressureControlled/.test(type)) {
        out.push(p.line([[x0, 0], [ax, 0], [ax, h * 0.9]], { cls: 'glyph-pilot', dashed: true }));
    } else if (x0 - ax > 3) {
        out.push(p.rect(ax, -ch * 0.3, x0, ch * 0.3, { cls: 'glyph-solenoid' }), p.line([[ax, ch * 0.3], [x0, -ch * 0.3]], { cls: 'glyph-solenoid' }));
    }
    if (!/Directional|PressureControlled/.test(type)) {
        // servo/proportional valve: parallel lines along the envelopes
        const d = Math.min((h - ch / 2) * 0.5, ch * 0.15);
        out.push(p.line([[x0, top - d], [x1, top - d]], { cls: 'glyph-servo' }), p.line([[x0, bottom + d], [x1, bottom + d]], { cls: 'glyph-servo' }));
    }
    return out;
}

/**
 * One envelope on the ports' line, the spring (adjustable: crossed by an arrow) on the right
 * and the dashed pilot on the left. Relief and sequence valves are normally closed: their
 * arrow sits off the ports' line; reducing valves are open: the arrow joins the ports and the
 * pilot comes from the outlet.
 */
export function pressureValve(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const ports = edgePorts(type, w, h);
    const cx = ports.length ? ports.reduce((sum, q) => sum + q[0], 0) / ports.length : 0;
    const side = Math.min(2 * h * 0.55, w * 0.8, (w - Math.abs(cx)) * 0.9);
    const [x, y] = [cx - side / 2, -side / 2];
    const reducing = /Reducing|Compensating|Drop/.test(type);
    const out: Glyph = [envelope(p, x, y, side, side)];
    const ax = reducing ? cx : x + side * 0.3;
    out.push(...p.arrow([ax, y + side * 0.85], [ax, y + side * 0.15], 'glyph-arrow'));
    for (const [px, py] of ports) out.push(p.line([[px, py], [px, py < 0 ? y : y + side]], { cls: 'glyph-port-line' }));
    const springEnd = Math.min(w * 0.97, x + side + side * 0.8);
    out.push(p.zigzag([x + side, 0], [springEnd, 0], side * 0.16, 5, 'glyph-spring'));
    if (/PressureRelief|Reducing/.test(type)) out.push(...p.arrow([x + side + side * 0.05, side * 0.35], [springEnd, -side * 0.35], 'glyph-adjust'));
    // pilot from the inlet (top, relief) or the outlet (bottom, reducing) to the left side
    const py = reducing ? y + side + (h - side / 2) * 0.5 : y - (h - side / 2) * 0.5;
    const px = Math.max(-w * 0.95, x - Math.min(side * 0.25, 6));
    out.push(p.line([[cx, py], [px, py], [px, 0], [x, 0]], { cls: 'glyph-pilot', dashed: true }));
    return out;
}

/** A ball on a V seat; pilot-operated ones get a pilot line, pre-loaded ones a spring. Lying or upright. */
export function checkValve(pen: Pen, type: string): Glyph {
    const p = pen.upright ? pen.transposed() : pen;
    const { w, h } = p;
    const r = Math.min(w * 0.35, h * 0.5) * 0.75;
    const out: Glyph = [p.line([[-w, 0], [-r * 1.2, 0]], { cls: 'glyph-port-line' }), p.circle([-r * 0.2, 0], r, { cls: 'glyph-ball' }),
        p.line([[r * 0.6, -r * 1.3], [r * 0.9, 0], [r * 0.6, r * 1.3]], { cls: 'glyph-seat' }), p.line([[r * 0.9, 0], [w, 0]], { cls: 'glyph-port-line' })];
    if (/Pilot|Poppet/.test(type)) out.push(p.line([[0, h * 0.95], [0, r * 1.15]], { cls: 'glyph-pilot', dashed: true }));
    if (/PreLoaded/.test(type)) out.push(p.zigzag([-w * 0.9, -r * 1.4], [-r * 1.1, -r * 0.4], r * 0.4, 4, 'glyph-spring'));
    if (/Orifice/.test(type)) {
        // an orifice in parallel: a bypass line with a throttle above the ball
        const yb = -Math.min(h * 0.75, r * 2.2);
        out.push(p.line([[-w * 0.8, 0], [-w * 0.8, yb], [w * 0.8, yb], [w * 0.8, 0]], { cls: 'glyph-port-line' }));
        out.push(p.curve((t) => [-r * 0.8 + 1.6 * r * t, yb - r * 0.35 + r * 0.25 * Math.sin(Math.PI * t)], 8),
            p.curve((t) => [-r * 0.8 + 1.6 * r * t, yb + r * 0.35 - r * 0.25 * Math.sin(Math.PI * t)], 8));
    }
    return out;
}

/** An envelope with a ball between two seats: flow from either inlet closes the other. */
export function shuttleValve(p: Pen): Glyph {
    const { w, h } = p;
    const r = Math.min(w * 0.12, h * 0.3);
    const out: Glyph = [envelope(p, -w * 0.7, -h * 0.6, w * 1.4, h * 1.2), p.line([[-w, 0], [w, 0]], { cls: 'glyph-port-line' }),
        p.line([[0, -h * 0.6], [0, -h]], { cls: 'glyph-port-line' }), p.circle([0, 0], r, { cls: 'glyph-ball', fill: p.fill })];
    for (const sgn of [-1, 1]) out.push(p.line([[sgn * r * 2.6, -r * 1.3], [sgn * r * 2.2, 0], [sgn * r * 2.6, r * 1.3]], { cls: 'glyph-seat' }));
    return out;
}

/** The valve symbol for a valve type, or null for types that are no valve (kept for the valve tests). */
export function valveGlyph(type: string, w: number, h: number): Glyph | null {
    if (!/Valve/.test(type) || /ValvePlate/.test(type)) return null;
    const p = new Pen(w, h);
    if (/ShuttleValve/.test(type)) return shuttleValve(p);
    if (/CheckValve|PoppetValve/.test(type) && !/Directional/.test(type)) return checkValve(p, type);
    if (/Pressure(Relief|Reducing|Compensating|Drop)|PressureControl(led)?Valve|CounterBalance|OverCenter/.test(type)) return pressureValve(p, type);
    return directionalValve(p, type);
}

