// Fluid-power symbols of our own in the ISO 1219 style: pumps and motors (circle and triangle),
// cylinders (barrel, piston, rod), accumulators, volumes and lines, orifices, tanks, sources.
import { Pen, edgePorts, portsOf, stubsToCircle, type Glyph, type Pt } from './draw';

/** Pneumatic symbols draw their triangles hollow, hydraulic ones filled (ISO 1219). */
const hollow = (type: string) => type.startsWith('Pneumatic');

/**
 * Pumps (triangle pointing out of the circle at the outlet) and motors (pointing in at the
 * inlet). The circle sits on the line of the fluid ports; the shaft is a double line to the
 * side the shaft port is on; variable machines get the diagonal arrow through the circle.
 */
export function pumpOrMotor(p: Pen, type: string, motor: boolean): Glyph {
    const { w, h } = p;
    const fluid = edgePorts(type, w, h);
    const cx = fluid.length ? fluid.reduce((sum, q) => sum + q[0], 0) / fluid.length : 0;
    const r = Math.min(h * 0.62, (w - Math.abs(cx)) * 0.9, w * 0.7);
    const c: Pt = [cx, 0];
    const out: Glyph = [p.circle(c, r, { cls: 'glyph-machine' }), ...stubsToCircle(p, fluid, c, r)];
    const tri = (apex: Pt, base: number, half: number, cls: string) =>
        p.poly([apex, [cx - half, base], [cx + half, base]], { cls, filled: !hollow(type), fill: hollow(type) ? p.fill : undefined });
    const up = -1;
    if (!motor || /Machine/.test(type)) out.push(tri([cx, up * r], up * r * 0.5, r * 0.3, 'glyph-pump-triangle'));
    if (motor) {
        // the inlet is on top in Hopsan's motors; a pump/motor machine also points in at the bottom
        const s = /Machine/.test(type) ? 1 : -1;
        out.push(tri([cx, s * r * 0.45], s * r * 0.92, r * 0.3, 'glyph-motor-triangle'));
    }
    if (/Variable|PressureControlled|Machine/.test(type)) {
        const d = r * 1.25;
        out.push(...p.arrow([cx - d * 0.75, d * 0.75], [cx + d * 0.75, -d * 0.75], 'glyph-variable'));
    }
    // the shaft: to the side of the first port that is not a fluid line
    const shaft = portsOf(type, w, h).find((q) => Math.abs(Math.abs(q.at[0]) - w) < 1e-6 && Math.abs(q.at[1]) < h * 0.3);
    const sx = shaft ? Math.sign(shaft.at[0]) : -1;
    const gap = Math.max(1.2, r * 0.07);
    out.push(p.line([[cx + sx * r, -gap], [sx * w, -gap]], { cls: 'glyph-shaft' }), p.line([[cx + sx * r, gap], [sx * w, gap]], { cls: 'glyph-shaft' }));
    return out;
}

/**
 * A barrel with the piston and its rod; the rod leaves the barrel towards the load port on the
 * right (both sides for symmetric cylinders). Only the barrel is solid: in Hopsan's layouts the
 * load sits on the rod, inside the box. Lying or upright.
 */
export function cylinder(pen: Pen, type: string): Glyph {
    const p = pen.upright ? pen.transposed() : pen;
    const { w, h } = p;
    // the barrel spans the fluid ports (they sit on its wall), leaving room for the rod
    const ports = pen.upright ? [] : edgePorts(type, w, h);
    const xs = ports.map((q) => q[0]);
    const bx0 = xs.length ? Math.max(-w * 0.97, Math.min(...xs) - w * 0.04) : -w * 0.8;
    const bx1 = xs.length ? Math.min(w * 0.5, Math.max(...xs) + w * 0.04, w * 0.4) : w * 0.4;
    const bh = h * 0.55;
    const px = bx0 + (bx1 - bx0) * 0.45;
    const rod = Math.max(p.sw, bh * 0.14);
    const out: Glyph = [p.rect(bx0, -bh, bx1, bh, { cls: 'icon-solid glyph-barrel', fill: p.fill }),
        p.rect(px - Math.max(1, (bx1 - bx0) * 0.03), -bh, px + Math.max(1, (bx1 - bx0) * 0.03), bh, { cls: 'glyph-piston', filled: true }),
        p.rect(px, -rod, w * 0.97, rod, { cls: 'glyph-rod', fill: p.fill })];
    if (/Symmetric/.test(type)) out.push(p.rect(-w * 0.97, -rod, px, rod, { cls: 'glyph-rod', fill: p.fill }));
    if (/SpringLoaded/.test(type)) out.push(p.zigzag([px + 2, -bh * 0.6], [bx1 - 1, -bh * 0.6], bh * 0.25, 5, 'glyph-spring'));
    for (const [x, y] of ports) out.push(p.line([[x, bh], [x, y]], { cls: 'glyph-port-line' }));
    if (/Mk?load/.test(type)) {
        // the load on the rod: a block with m
        const m0 = bx1 + (w - bx1) * 0.45;
        out.push(p.rect(m0, -bh, w * 0.97, bh, { cls: 'glyph-mass' }), p.fitText('m', bh * 1.4, (w * 0.97 - m0) / 2, bh, [(m0 + w * 0.97) / 2, 0]));
    }
    return out;
}

/** An upright capsule on its port with the separating element (diaphragm, piston) across it. */
export function accumulator(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const rw = Math.min(w * 0.7, h * 0.4);
    const top = -h * 0.75;
    const bottom = h * 0.6;
    const capsule = [...Pen.arc([0, top + rw], rw, Math.PI, 2 * Math.PI), ...Pen.arc([0, bottom - rw], rw, 0, Math.PI)];
    const out: Glyph = [p.poly(capsule, { cls: 'glyph-accumulator' }), p.line([[0, bottom], [0, h]], { cls: 'glyph-port-line' })];
    const my = (top + bottom) / 2;
    if (/Piston/.test(type)) out.push(p.line([[-rw, my - 1.5], [rw, my - 1.5]]), p.line([[-rw, my + 1.5], [rw, my + 1.5]]));
    else out.push(p.line([[-rw, my], [rw, my]], { cls: 'glyph-diaphragm' }));
    // gas-loaded: the filled triangle of a gas in the upper chamber
    const t = rw * 0.45;
    out.push(p.poly([[0, top + rw * 0.4], [-t, top + rw * 0.4 + t * 1.2], [t, top + rw * 0.4 + t * 1.2]], { filled: true }));
    return out;
}

/** A fluid volume or a hose: a rounded chamber (hoses wavy) on the line through it. */
export function volume(p: Pen, type: string): Glyph {
    const { w, h } = p;
    if (/Hose/.test(type)) {
        const y = portsOf(type, w, h)[0]?.at[1] ?? 0;
        const a = Math.min(h * 0.35, h - Math.abs(y));
        return [p.curve((t) => [-w + 2 * w * t, y + a * Math.sin(t * Math.PI * 4)], 32, { cls: 'glyph-hose' })];
    }
    const [rx, ry] = [w * 0.85, h * 0.55];
    const r = ry;
    const outline = [...Pen.arc([rx - r, 0], r, -Math.PI / 2, Math.PI / 2), ...Pen.arc([-rx + r, 0], r, Math.PI / 2, 1.5 * Math.PI)];
    return [p.poly(outline, { cls: 'glyph-volume' }), p.line([[-w, 0], [w, 0]], { cls: 'glyph-port-line' })];
}

/** Lossless lines and connectors: the line itself, a T with its junction dot. */
export function line(p: Pen, type: string): Glyph {
    const { w, h } = p;
    if (/TConnector/.test(type)) {
        const y = -h * 0.84;
        return [p.line([[-w, y], [w, y]], { cls: 'glyph-port-line' }), p.line([[0, y], [0, h]], { cls: 'glyph-port-line' }), p.circle([0, y], Math.min(h * 0.15, 2.5), { filled: true })];
    }
    const out: Glyph = [p.line([[-w, 0], [w, 0]], { cls: 'glyph-port-line' })];
    if (/TLM/.test(type)) out.push(p.line([[-w * 0.6, -h * 0.6], [-w * 0.6, h * 0.6]]), p.line([[w * 0.6, -h * 0.6], [w * 0.6, h * 0.6]]));
    return out;
}

/**
 * Restrictions on the line through the box: laminar (viscous) ones as two arcs, turbulent
 * (sharp-edged) ones as two V notches; an input for the opening makes them adjustable (arrow).
 */
export function orifice(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const a = Math.min(w * 0.3, h * 0.7);
    const g = a * 0.25;
    const out: Glyph = [p.line([[-w, 0], [-a, 0]], { cls: 'glyph-port-line' }), p.line([[a, 0], [w, 0]], { cls: 'glyph-port-line' })];
    if (/Laminar/.test(type)) {
        out.push(p.curve((t) => [-a + 2 * a * t, -a * 0.8 + (a * 0.8 - g) * Math.sin(Math.PI * t)], 10, { cls: 'glyph-throttle' }),
            p.curve((t) => [-a + 2 * a * t, a * 0.8 - (a * 0.8 - g) * Math.sin(Math.PI * t)], 10, { cls: 'glyph-throttle' }));
    } else {
        out.push(p.line([[-a * 0.5, -a * 0.8], [0, -g], [a * 0.5, -a * 0.8]], { cls: 'glyph-throttle' }), p.line([[-a * 0.5, a * 0.8], [0, g], [a * 0.5, a * 0.8]], { cls: 'glyph-throttle' }));
    }
    if (portsOf(type, w, h).some((q) => !/^P/.test(q.name))) out.push(...p.arrow([-a * 0.9, a * 0.9], [a * 0.9, -a * 0.9], 'glyph-adjust'));
    return out;
}

/** An open tank with the line from the port on top reaching into it. */
export function tank(p: Pen): Glyph {
    const { w, h } = p;
    const tw = Math.min(w * 0.85, h * 1.1);
    const top = -h * 0.15;
    return [p.line([[-tw, top], [-tw, h * 0.8], [tw, h * 0.8], [tw, top]], { cls: 'glyph-tank' }), p.line([[0, -h], [0, h * 0.45]], { cls: 'glyph-port-line' })];
}

/** A plugged port: the line ends on a bar. */
export function plug(p: Pen): Glyph {
    const { w, h } = p;
    return [p.line([[0, -h], [0, h * 0.2]], { cls: 'glyph-port-line' }), p.line([[-w * 0.6, h * 0.2], [w * 0.6, h * 0.2]], { cls: 'glyph-block' })];
}

/**
 * Pressure and flow sources: a circle with the filled triangle pointing out of it towards the
 * power port (ISO's energy source), p or q inside. A sensor's circle holds a pointer instead.
 */
export function fluidSource(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const port = portsOf(type, w, h).find((q) => /^P/.test(q.name))?.at ?? [0, -h];
    const r = p.u * 0.72;
    const len = Math.hypot(port[0], port[1]) || 1;
    const [ux, uy] = [port[0] / len, port[1] / len];
    const out: Glyph = [p.circle([0, 0], r, { cls: 'glyph-source' }), p.line([[ux * r, uy * r], port], { cls: 'glyph-port-line' })];
    const [nx, ny] = [-uy, ux];
    const base = r * 0.45;
    out.push(p.poly([[ux * r, uy * r], [ux * base + nx * r * 0.32, uy * base + ny * r * 0.32], [ux * base - nx * r * 0.32, uy * base - ny * r * 0.32]],
        { cls: 'glyph-source-triangle', filled: !hollow(type), fill: hollow(type) ? p.fill : undefined }));
    out.push(p.fitText(/Flow|^PneumaticQ/.test(type) ? 'q' : 'p', r * 0.9, r * 0.45, r * 0.4, [-ux * r * 0.35, -uy * r * 0.35]));
    return out;
}
