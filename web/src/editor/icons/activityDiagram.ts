// Activity diagram blocks as UML draws them: actions as rounded boxes, decisions and merges as
// diamonds, forks and joins as a thick bar, the start as a filled dot, the end as a bull's eye,
// connectors and edges as the arrow between them (an edge with its guard bar).
import { Pen, portsOf, type Glyph } from './draw';

export function activityNode(p: Pen, type: string): Glyph {
    const { w, h } = p;
    const kind = type.replace(/^ActivityDiagram/, '').replace(/(N|0)$/, '');
    switch (kind) {
        case 'Action':
            return [p.roundedRect(-w * 0.85, -h * 0.7, w * 0.85, h * 0.7, h * 0.45, { cls: 'glyph-action', fill: '#fff' })];
        case 'Decision':
        case 'Merge': {
            const r = p.u * 0.8;
            return [p.poly([[0, -r], [r, 0], [0, r], [-r, 0]], { cls: 'glyph-diamond', fill: '#fff' })];
        }
        case 'Fork':
        case 'Join': {
            // the bar, and short lines out to the ports on its sides
            const bar = Math.max(p.sw, w * 0.18);
            const out: Glyph = [p.rect(-bar / 2, -h * 0.9, bar / 2, h * 0.9, { filled: true, cls: 'glyph-bar' })];
            for (const { at } of portsOf(type, w, h)) if (Math.abs(Math.abs(at[0]) - w) < 1e-6) out.push(p.line([at, [Math.sign(at[0]) * bar / 2, at[1]]], { cls: 'glyph-port-line' }));
            return out;
        }
        case 'InitiateState': {
            const r = p.h * 0.6;
            return [p.circle([-w * 0.35, 0], r, { filled: true }), ...p.arrow([-w * 0.35 + r, 0], [w, 0], 'glyph-arrow')];
        }
        case 'Final':
        case 'FinalNode': {
            const r = p.u * 0.8;
            const c: [number, number] = kind === 'Final' ? [w - r * 1.1, 0] : [0, 0];
            const out: Glyph = [p.circle(c, r, { cls: 'glyph-final' }), p.circle(c, r * 0.55, { filled: true })];
            if (kind === 'Final') out.unshift(...p.arrow([-w, 0], [c[0] - r, 0], 'glyph-arrow'));
            return out;
        }
        case 'Edge':
            return [...p.arrow([-w, 0], [w, 0], 'glyph-arrow'), p.line([[-w * 0.05, -h * 0.8], [-w * 0.05, h * 0.8]], { cls: 'glyph-guard' })];
        default:
            // the connector: the arrow alone
            return p.arrow([-w, 0], [w, 0], 'glyph-arrow');
    }
}
