// The animation facts the app needs at run time, extracted from
// ../shared/reference/animation.json (measured from Hopsan's animation descriptions) into a
// compact form of our own: per type, each movable part's driving port variables, its movement,
// rotation pivot, resize, colour and the user's handles (adjustable, switchable). Numbers are
// numbers, indices are positions in `data`, and points are [x, y] in Hopsan's icon frame (top
// left origin, the type's icon size). The app cannot read ../shared, so the extract is
// committed; a unit test fails when it is stale.
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

export const sourceFile = fileURLToPath(new URL('../../../shared/reference/animation.json', import.meta.url));
const appearanceFile = fileURLToPath(new URL('../../../shared/reference/appearance.json', import.meta.url));
export const extractFile = fileURLToPath(new URL('../src/animation/animation.generated.json', import.meta.url));

/** A number from the facts' text ("" and missing: 0). */
const num = (text) => {
    const v = Number(text ?? 0);
    return Number.isFinite(v) ? v : 0;
};
const index = (text) => (text === undefined || text === null ? 0 : num(text));
/** The divisor's parameter name, when one is set. */
const divisorOf = (entry) => (entry.divisor ? { divisor: entry.divisor } : {});

function movable(m) {
    const out = { data: (m.data ?? []).slice().sort((a, b) => index(a.idx) - index(b.idx)).map((d) => [d.port, d.dataname]) };
    const start = m.start?.[0];
    out.start = start ? [num(start.x), num(start.y), num(start.a)] : [0, 0, 0];
    if (m.movement?.length) {
        out.move = m.movement.map((e) => ({ x: num(e.x), y: num(e.y), a: num(e.a), data: index(e.idx), ...divisorOf(e),
            ...(e.multiplier ? { multiplier: e.multiplier } : {}) }));
    }
    if (m.transformorigin?.[0]) out.origin = [num(m.transformorigin[0].x), num(m.transformorigin[0].y)];
    if (m.resize?.length) {
        out.resize = m.resize.map((e) => ({ x: num(e.x), y: num(e.y), data: index(e.idx1 ?? e.idx),
            ...(e.idx2 !== undefined ? { minus: index(e.idx2) } : {}), ...divisorOf(e) }));
        const s = m.initscale?.[0];
        out.initScale = s ? [num(s.x), num(s.y)] : [1, 1];
    }
    if (m.color?.length) {
        const c = m.initcolor?.[0] ?? {};
        out.initColour = [num(c.r), num(c.g), num(c.b)];
        out.colour = m.color.map((e) => ({ rgb: [num(e.r), num(e.g), num(e.b)], data: index(e.idx), ...divisorOf(e) }));
    }
    if (m.movingport?.length) out.movingPorts = m.movingport.map((p) => ({ port: p.portname, at: [num(p.startx), num(p.starty)] }));
    const adj = m.adjustable?.[0];
    if (adj) {
        out.adjustable = { port: adj.port, dataname: adj.dataname, x: [num(adj.xmin), num(adj.xmax)], y: [num(adj.ymin), num(adj.ymax)],
            gain: [num(adj.xgain), num(adj.ygain)] };
    }
    const sw = m.switchable?.[0];
    if (sw) out.switchable = { port: sw.port, dataname: sw.dataname, on: num(sw.onvalue), off: num(sw.offvalue), momentary: sw.momentary === 'true' };
    const ind = m.indicator?.[0];
    if (ind) out.indicator = { port: ind.port, dataname: ind.dataname };
    return out;
}

export function extractAnimation() {
    for (const f of [sourceFile, appearanceFile]) if (!existsSync(f)) throw new Error(`facts not found at ${f} (../shared is missing)`);
    const facts = JSON.parse(readFileSync(sourceFile, 'utf8'));
    const appearance = JSON.parse(readFileSync(appearanceFile, 'utf8')).types;
    const types = {};
    for (const [type, t] of Object.entries(facts.types)) {
        if (!t.movables?.length) continue;
        const icon = appearance[type]?.icon;
        types[type] = { size: [icon?.width ?? 40, icon?.height ?? 40], movables: t.movables.map(movable) };
    }
    return JSON.stringify({ source: facts.source, types }, null, 0) + '\n';
}
