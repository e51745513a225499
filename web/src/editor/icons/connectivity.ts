// Links to the world outside the model: co-simulation interfaces as a line ending in a socket
// (with the kind, C, Q or TLM, beside it), signal interfaces as an arrow through the socket, and
// FMU wrappers as a chip with pins on both sides.
import { Pen, type Glyph } from './draw';

/** The socket: a cup open to the left at x, on the centre line. */
function socket(p: Pen, x: number, r: number): SVGElement {
    return p.line(Pen.arc([x, 0], r, Math.PI / 2, -Math.PI / 2, 10), { cls: 'glyph-socket' });
}

export function interfacePort(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const r = Math.min(h * 0.45, w * 0.35);
    const cup = w * 0.05;
    const out: Glyph = [socket(p, cup, r)];
    if (/^SignalInput/.test(type)) out.push(...p.arrow([-w * 0.5, 0], [w, 0], 'glyph-arrow'));
    else if (/^SignalOutput/.test(type)) out.push(...p.arrow([-w, 0], [cup + r * 0.6, 0], 'glyph-arrow'));
    else out.push(p.line([[-w, 0], [cup + r * 0.5, 0]], { cls: 'glyph-port-line' }), p.circle([cup + r * 0.5, 0], Math.max(0.8, r * 0.22), { filled: true }));
    const kind = /TLM$/.test(type) ? 'TLM' : /C$/.test(type) ? 'C' : /Q$/.test(type) ? 'Q' : '';
    // the kind above the incoming line, clear of the socket
    if (kind) out.push(p.fitText(kind, h * 0.5, w * 0.4, h * 0.35, [-w * 0.5, -h * 0.5]));
    return out;
}

/** A functional mock-up unit: a chip with pins and its name. */
export function fmu(p: Pen): Glyph {
    const { w, h } = p;
    const [x0, y0] = [w * 0.6, h * 0.7];
    const out: Glyph = [p.rect(-x0, -y0, x0, y0, { cls: 'glyph-chip', fill: '#fff' })];
    for (let i = 0; i < 4; i++) {
        const y = -y0 + ((2 * y0) * (i + 0.5)) / 4;
        out.push(p.line([[-w * 0.85, y], [-x0, y]], { cls: 'glyph-pin' }), p.line([[x0, y], [w * 0.85, y]], { cls: 'glyph-pin' }));
    }
    out.push(p.fitText('FMU', h * 0.6, x0 * 0.8, y0 * 0.5));
    return out;
}
