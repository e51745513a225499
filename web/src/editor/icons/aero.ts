// Aircraft and their parts, drawn as what they are: the aircraft from above, a rocket with its
// thrust-vectoring nozzle, a jet engine's nacelle with its fan, a propeller, a fuel tank with its
// level, a rocket combustion chamber and nozzle, the atmosphere as layers thinning upwards, wind
// as streaks, and the flight recorder as a box with a flight track.
import { Pen, type Glyph, type Pt } from './draw';

/** An aircraft seen from above, nose up, scaled to the half side s around c. */
function planform(p: Pen, c: Pt, s: number, cls = 'glyph-aircraft'): SVGElement {
    const outline: Pt[] = [
        [0, -1], [0.09, -0.85], [0.1, -0.25], [0.95, 0.12], [0.95, 0.25], [0.1, 0.15], [0.08, 0.65], [0.38, 0.85], [0.38, 0.95], [0, 0.9],
    ];
    const both = [...outline, ...outline.slice(0, -1).reverse().map(([x, y]): Pt => [-x, y])];
    return p.poly(both.map(([x, y]): Pt => [c[0] + x * s, c[1] + y * s]), { cls, fill: '#fff' });
}

export function aircraft(p: Pen): Glyph {
    // the ports line the edges: the aircraft stays in the middle, clear of them
    return [planform(p, [0, 0], p.u * 0.85)];
}

/** A rocket lying nose right: body, nose cone, fins and the swivelling nozzle at the tail. */
export function rocket(p: Pen): Glyph {
    const { w, h } = p;
    const [r, x0, x1] = [h * 0.35, -w * 0.8, w * 0.55];
    return [
        p.poly([[x0, -r], [x1, -r], [w * 0.85, 0], [x1, r], [x0, r]], { cls: 'glyph-rocket', fill: '#fff' }),
        p.poly([[x0 + r, -r], [x0 - r * 0.3, -h * 0.8], [x0 - r * 0.3, -r]], { cls: 'glyph-fin' }),
        p.poly([[x0 + r, r], [x0 - r * 0.3, h * 0.8], [x0 - r * 0.3, r]], { cls: 'glyph-fin' }),
        p.poly([[x0, -r * 0.5], [-w * 0.92, -r * 0.8], [-w * 0.92, r * 0.2], [x0, r * 0.5]], { cls: 'glyph-nozzle' }),
    ];
}

/** A jet engine from the side: intake with its fan on the left, the nacelle narrowing to the exhaust. */
export function jetEngine(p: Pen): Glyph {
    const { w, h } = p;
    const [x0, x1, r0, r1] = [-w * 0.8, w * 0.8, h * 0.62, h * 0.35];
    return [
        p.poly([[x0, -r0], [x0 + w * 0.9, -r0], [x1, -r1], [x1, r1], [x0 + w * 0.9, r0], [x0, r0]], { cls: 'glyph-nacelle', fill: '#fff' }),
        p.line([[x0 + w * 0.12, -r0 * 0.85], [x0 + w * 0.12, r0 * 0.85]], { cls: 'glyph-fan' }),
        p.poly([[x0 + w * 0.04, -r0 * 0.3], [x0 + w * 0.3, 0], [x0 + w * 0.04, r0 * 0.3]], { cls: 'glyph-spinner' }),
        p.line([[x0 + w * 0.3, 0], [x1 - w * 0.05, 0]], { cls: 'glyph-shaft', dashed: true }),
    ];
}

/** A propeller seen from the side: two blades on a hub, its shaft to the right. */
export function propeller(p: Pen): Glyph {
    const { w, h } = p;
    const bw = w * 0.45;
    return [
        p.ellipse([-w * 0.2, -h * 0.45], bw, h * 0.4, { cls: 'glyph-blade' }),
        p.ellipse([-w * 0.2, h * 0.45], bw, h * 0.4, { cls: 'glyph-blade' }),
        p.line([[-w * 0.2, 0], [w, 0]], { cls: 'glyph-shaft' }),
        p.circle([-w * 0.2, 0], Math.min(w * 0.35, h * 0.1), { filled: true }),
    ];
}

/** A tank of rounded ends, its fuel level across it and the fuel below the level hatched faint. */
export function fuelTank(p: Pen): Glyph {
    const { w, h } = p;
    const [hw, hh] = [w * 0.82, h * 0.62];
    const level = hh * 0.1;
    const out: Glyph = [p.roundedRect(-hw, -hh, hw, hh, hh, { cls: 'glyph-tank', fill: '#fff' }), p.line([[-hw + hh * 0.5, level], [hw - hh * 0.5, level]], { cls: 'glyph-level' })];
    for (let i = 1; i < 6; i++) {
        const x = -hw + hh + ((2 * hw - 2 * hh) * i) / 6;
        out.push(p.line([[x - hh * 0.25, hh * 0.8], [x + hh * 0.25, level + hh * 0.15]], { faint: true }));
    }
    return out;
}

/** A rocket combustion chamber on top of its bell nozzle, thrust pointing up. */
export function combustionChamber(p: Pen): Glyph {
    const { w, h } = p;
    const [cw, top, throat, exit] = [w * 0.35, -h * 0.75, -h * 0.05, h * 0.8];
    return [
        p.poly([[-cw, top], [cw, top], [cw, throat - h * 0.2], [cw * 0.35, throat], [w * 0.7, exit], [-w * 0.7, exit], [-cw * 0.35, throat], [-cw, throat - h * 0.2]], { cls: 'glyph-chamber', fill: '#fff' }),
        ...p.arrow([0, top + h * 0.35], [0, -h * 0.95], 'glyph-arrow'),
    ];
}

/** Air layers, closer together near the ground, an altitude arrow beside them. */
export function atmosphere(p: Pen): Glyph {
    const { w, h } = p;
    const out: Glyph = [...p.hatch([-w * 0.85, h * 0.75], [w * 0.85, h * 0.75], h * 0.15, -1, 8)];
    for (const [i, y] of [0.45, 0.15, -0.25, -0.7].entries()) {
        out.push(p.curve((t) => [-w * 0.5 + t * w * 1.3, h * y + Math.sin(t * Math.PI * 4) * h * 0.05], 24, { cls: 'glyph-air', faint: i > 1 }));
    }
    out.push(...p.arrow([-w * 0.75, h * 0.6], [-w * 0.75, -h * 0.85], 'glyph-arrow'));
    return out;
}

/** Wind: three streaks, each ending in a curl. */
export function wind(p: Pen): Glyph {
    const { w, h } = p;
    const out: Glyph = [];
    for (const [y, len] of [[-0.5, 0.9], [0, 1.3], [0.5, 0.7]]) {
        const [x0, x1] = [-w * 0.85, -w * 0.85 + w * len];
        const r = h * 0.14;
        out.push(p.line([[x0, y * h], [x1, y * h], ...Pen.arc([x1, y * h - r], r, Math.PI / 2, -Math.PI, 10)], { cls: 'glyph-wind' }));
    }
    return out;
}

/** The flight recorder: a box with a recorded track and the aircraft on it. */
export function flightRecorder(p: Pen): Glyph {
    const { w, h } = p;
    return [
        p.rect(-w * 0.75, -h * 0.75, w * 0.75, h * 0.75, { cls: 'glyph-recorder' }),
        p.curve((t) => [-w * 0.6 + t * w * 1.0, h * 0.5 - t * h * 0.8 + Math.sin(t * Math.PI * 2) * h * 0.2], 20, { cls: 'glyph-track', dashed: true }),
        planform(p, [w * 0.42, -h * 0.35], p.u * 0.25),
    ];
}
