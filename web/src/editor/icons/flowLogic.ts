// Logic of the flow of a simulation: functional flow blocks (the function box with its number
// strip; AND, OR and loop nodes as circles, their closing nodes doubled), signal routers as a
// selector switch, a counter, a steady-state detector and the stop sign that ends a run.
import { Pen, portsOf, type Glyph, type Pt } from './draw';

/** A functional flow block: a function box (number strip on top) or a logic node as a circle. */
export function functionalFlowBlock(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const node = type.replace(/^SignalFFB/, '');
    if (!node) {
        const [x0, y0] = [w * 0.8, h * 0.7];
        return [p.rect(-x0, -y0, x0, y0, { cls: 'glyph-function', fill: '#fff' }), p.line([[-x0, -y0 * 0.35], [x0, -y0 * 0.35]], { cls: 'glyph-function' }),
            p.line([[-x0 * 0.3, -y0], [-x0 * 0.3, -y0 * 0.35]], { cls: 'glyph-function' }), p.fitText('f', y0, x0 * 0.5, y0 * 0.45, [0, y0 * 0.3])];
    }
    const r = p.u * 0.72;
    const out: Glyph = [p.circle([0, 0], r, { cls: 'glyph-node', fill: '#fff' })];
    // the node closing a branch draws a second ring
    if (/In$/.test(node)) out.push(p.circle([0, 0], r * 0.8, { cls: 'glyph-node' }));
    if (/^loop/.test(node)) {
        // a circular arrow: the arc, its head on the last stretch
        const arc = Pen.arc([0, 0], r * 0.45, -Math.PI * 0.15, Math.PI * 1.3, 12);
        out.push(p.line(arc.slice(0, -1), { cls: 'glyph-loop' }), ...p.arrow(arc[10], arc[12], 'glyph-loop', r * 0.3));
    } else out.push(p.fitText(/^and/.test(node) ? '&' : '≥1', r, r * 0.55, r * 0.4));
    return out;
}

/** A selector switch: the inputs on the left, the blade from one of them to the output, the route from above. */
export function router(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const inputs = portsOf(type, w, h).filter((q) => /^in\d/.test(q.name)).map((q) => q.at);
    const pivot: Pt = [w * 0.45, 0];
    const dot = Math.max(0.7, p.sw * 0.9);
    const out: Glyph = inputs.flatMap(([x, y]) => [p.line([[x, y], [-w * 0.35, y]], { cls: 'glyph-port-line' }), p.circle([-w * 0.35, y], dot, { filled: true })]);
    const chosen = inputs[0] ?? [-w, 0];
    out.push(p.line([pivot, [-w * 0.3, chosen[1] + h * 0.05]], { cls: 'glyph-switch' }), p.line([pivot, [w, 0]], { cls: 'glyph-port-line' }), p.circle(pivot, dot, { filled: true }));
    out.push(p.line([[0, -h], [0, -h * 0.35]], { cls: 'glyph-reference', dashed: true }));
    return out;
}

/** A counter: its count on a tally of ticks. */
export function counter(p: Pen): Glyph {
    const { w, h } = p;
    const out: Glyph = [];
    for (let i = 0; i < 4; i++) out.push(p.line([[-w * 0.55 + i * w * 0.22, -h * 0.55], [-w * 0.55 + i * w * 0.22, h * 0.55]], { cls: 'glyph-tally' }));
    out.push(p.line([[-w * 0.7, h * 0.4], [w * 0.25, -h * 0.4]], { cls: 'glyph-tally' }), p.fitText('n', h * 0.9, w * 0.15, h * 0.5, [w * 0.62, 0]));
    return out;
}

/** Steady state: a response settling onto a flat line, marked where it is found steady. */
export function steadyState(p: Pen): Glyph {
    const { w, h } = p;
    const [x0, x1, y] = [-w * 0.8, w * 0.8, -h * 0.3];
    return [
        p.curve((t) => [x0 + (x1 - x0) * t, y + h * 0.9 * Math.exp(-5 * t) * Math.cos(12 * t)], 28, { cls: 'glyph-wave' }),
        p.line([[w * 0.35, -h * 0.8], [w * 0.35, h * 0.8]], { cls: 'glyph-axis', dashed: true, faint: true }),
    ];
}

/** The stop sign: an octagon. */
export function stopSimulation(p: Pen): Glyph {
    const r = p.u * 0.85;
    const k = r * Math.tan(Math.PI / 8);
    const pts: Pt[] = [[-k, -r], [k, -r], [r, -k], [r, k], [k, r], [-k, r], [-r, k], [-r, -k]];
    return [p.poly(pts, { cls: 'glyph-stop', fill: '#fff' }), p.fitText('STOP', r, r * 0.8, r * 0.4)];
}
