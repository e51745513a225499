// Whole machines and vehicles: a car from the side on its two driven wheels, a piston engine
// turning its crank, a fork-lift mast with its forks, and the parts of an axial piston machine
// (the valve plate with its two kidney ports, the swash plate with the pistons on it).
import { Pen, portsOf, type Glyph, type Pt } from './draw';

/** A car from the side; its wheels stand on the driven wheel ports (Pmr1, Pmr2) of the bottom edge. */
export function vehicle(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const wheels = portsOf(type, w, h).filter((q) => /^Pmr/.test(q.name)).map((q) => q.at[0]);
    const xs = wheels.length === 2 ? wheels : [-w * 0.6, w * 0.6];
    const r = Math.min(h * 0.3, w * 0.15);
    const ground = h - r;
    const sill = ground - r * 0.2;
    const body: Pt[] = [[-w * 0.9, sill], [-w * 0.9, -h * 0.05], [-w * 0.45, -h * 0.15], [-w * 0.25, -h * 0.7], [w * 0.35, -h * 0.7], [w * 0.6, -h * 0.15], [w * 0.9, -h * 0.05], [w * 0.9, sill]];
    return [
        p.poly(body, { cls: 'glyph-car', fill: '#fff' }),
        p.line([[-w * 0.2, -h * 0.6], [-w * 0.38, -h * 0.15], [w * 0.48, -h * 0.15], [w * 0.3, -h * 0.6], [-w * 0.2, -h * 0.6]], { cls: 'glyph-window' }),
        ...xs.flatMap((x) => [p.circle([x, ground], r, { cls: 'glyph-wheel', fill: '#fff' }), p.circle([x, ground], r * 0.3, { filled: true })]),
    ];
}

/** A piston engine: a cylinder with its piston, the rod down to the crank, the shaft out to its port. */
export function combustionEngine(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const shaft = portsOf(type, w, h).find((q) => q.name === 'P1')?.at ?? [w, h * 0.6];
    const crank: Pt = [-w * 0.1, shaft[1]];
    const r = Math.min(h * 0.2, w * 0.2);
    const [cw, top, piston] = [w * 0.3, -h * 0.85, -h * 0.25];
    return [
        p.line([[-cw, piston + h * 0.35], [-cw, top], [cw, top], [cw, piston + h * 0.35]], { cls: 'glyph-cylinder' }),
        p.rect(-cw * 0.85, piston - h * 0.2, cw * 0.85, piston, { cls: 'glyph-piston', fill: '#fff' }),
        p.circle(crank, r, { cls: 'glyph-crank' }),
        p.line([[0, piston - h * 0.1], [crank[0] + r * 0.7, crank[1] - r * 0.7]], { cls: 'glyph-rod' }),
        p.line([crank, shaft], { cls: 'glyph-shaft' }),
        // the spark plug on top
        p.line([[0, top], [0, -h * 0.97]], { cls: 'glyph-plug' }),
    ];
}

/** A fork-lift mast: two rails, the carriage on them and the fork reaching out to the right. */
export function forkLift(p: Pen): Glyph {
    const { w, h } = p;
    const [x0, x1, top, bottom] = [-w * 0.6, -w * 0.3, -h * 0.85, h * 0.85];
    return [
        p.line([[x0, bottom], [x0, top]], { cls: 'glyph-rail' }),
        p.line([[x1, bottom], [x1, top]], { cls: 'glyph-rail' }),
        p.rect(x1, -h * 0.1, x1 + w * 0.15, h * 0.35, { cls: 'glyph-carriage', fill: '#fff' }),
        p.poly([[x1 + w * 0.15, h * 0.35], [w * 0.8, h * 0.35], [w * 0.8, h * 0.42], [x1 + w * 0.22, h * 0.42], [x1 + w * 0.22, -h * 0.05], [x1 + w * 0.15, -h * 0.05]], { cls: 'glyph-fork', filled: true }),
    ];
}

/** The valve plate: a disc with two kidney-shaped ports, inlet and outlet. */
export function valvePlate(p: Pen): Glyph {
    const r = p.u * 0.8;
    const k = (a0: number, a1: number) => {
        const [ro, ri] = [r * 0.72, r * 0.52];
        return p.poly([...Pen.arc([0, 0], ro, a0, a1, 10), ...Pen.arc([0, 0], ri, a1, a0, 10)], { cls: 'glyph-kidney' });
    };
    return [p.circle([0, 0], r, { cls: 'glyph-plate', fill: '#fff' }), k(-Math.PI * 0.4, Math.PI * 0.4), k(Math.PI * 0.6, Math.PI * 1.4), p.circle([0, 0], r * 0.15, { cls: 'glyph-hub' })];
}

/** The swash plate tilted across the shaft, pistons resting on it (the cylinder block drawn with them). */
export function swashPlate(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const tilt = h * 0.35;
    const plateX = -w * 0.45;
    const out: Glyph = [
        p.poly([[plateX - w * 0.06 - tilt * 0.3, -h * 0.8], [plateX - tilt * 0.3 + w * 0.02, -h * 0.8], [plateX + tilt * 0.3 + w * 0.02, h * 0.8], [plateX - w * 0.06 + tilt * 0.3, h * 0.8]], { cls: 'glyph-swash', filled: true }),
        p.line([[-w * 0.95, 0], [w * 0.9, 0]], { cls: 'glyph-shaft', dashed: true }),
    ];
    const block = /CylinderBlock/.test(type);
    for (const y of [-0.45, 0.45]) {
        const x = plateX + tilt * 0.3 * y / 0.8 + w * 0.04;
        out.push(p.rect(x, h * y - h * 0.13, x + w * 0.3, h * y + h * 0.13, { cls: 'glyph-piston', fill: '#fff' }));
    }
    if (block) out.push(p.rect(-w * 0.1, -h * 0.75, w * 0.5, h * 0.75, { cls: 'glyph-block' }));
    return out;
}
