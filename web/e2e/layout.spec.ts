// Issue 13.5: bodies and ports drawn at Hopsan's sizes and positions (appearance.json and the
// .hmf pose), lines re-routed to their ports, names above the bodies.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect, type Page } from './fixtures';
import { login, openExample } from './helpers';

interface Rect { x0: number; y0: number; x1: number; y1: number }
interface Drawn {
    bodies: { name: string; type: string; angle: number; frame: Rect; solid: Rect[]; label: Rect | null }[];
    ports: { component: string; port: string; x: number; y: number }[];
    lines: { from: string; to: string; points: [number, number][] }[];
    saved: { from: string; to: string; points: [number, number][] }[];
}

const appearance = JSON.parse(readFileSync(fileURLToPath(new URL('../../../shared/reference/appearance.json', import.meta.url)), 'utf8')) as
    { types: Record<string, { icon: { width: number; height: number } }> };

/** What the canvas drew, in scene coordinates, and the line points the server stored. */
async function drawn(page: Page): Promise<Drawn> {
    return page.evaluate(() => {
        const app = (window as unknown as { __tlmhub: { canvas: { sceneFromClient(x: number, y: number): { x: number; y: number } };
            store: { system: { components: { name: string; pose: { angle: number } }[]; connections: { from: { component: string; port: string }; to: { component: string; port: string }; points: [number, number][] }[] } } } }).__tlmhub;
        const scene = (el: Element) => {
            const r = el.getBoundingClientRect();
            const a = app.canvas.sceneFromClient(r.left, r.top);
            const b = app.canvas.sceneFromClient(r.right, r.bottom);
            return { x0: a.x, y0: a.y, x1: b.x, y1: b.y };
        };
        const angles = new Map(app.store.system.components.map((c) => [c.name, c.pose.angle]));
        const bodies = [...document.querySelectorAll('.canvas .component:not(.system-port):not(.subsystem)')].map((el) => {
            const label = el.querySelector('.component-label');
            return { name: el.getAttribute('data-name')!, type: el.getAttribute('data-type')!, angle: angles.get(el.getAttribute('data-name')!) ?? 0,
                frame: scene(el.querySelector('.icon-frame')!), solid: [...el.querySelectorAll('.icon-solid')].map(scene), label: label ? scene(label) : null };
        });
        const ports = [...document.querySelectorAll('.canvas .port:not(.parameter)')].map((el) => {
            const r = scene(el);
            return { component: el.getAttribute('data-component')!, port: el.getAttribute('data-port')!, x: (r.x0 + r.x1) / 2, y: (r.y0 + r.y1) / 2 };
        });
        const lines = [...document.querySelectorAll('.canvas .connection')].map((el) => ({
            from: el.getAttribute('data-from')!, to: el.getAttribute('data-to')!,
            points: el.getAttribute('points')!.split(' ').map((p) => p.split(',').map(Number) as [number, number]),
        }));
        const saved = app.store.system.connections.map((c) => ({ from: `${c.from.component}.${c.from.port}`, to: `${c.to.component}.${c.to.port}`, points: c.points }));
        return { bodies, ports, lines, saved };
    });
}

const dist = (a: { x: number; y: number }, b: [number, number]) => Math.hypot(a.x - b[0], a.y - b[1]);
const overlap = (a: Rect, b: Rect) => Math.max(0, Math.min(a.x1, b.x1) - Math.max(a.x0, b.x0)) * Math.max(0, Math.min(a.y1, b.y1) - Math.max(a.y0, b.y0));

test('Position Servo: bodies at their Hopsan size, ports on the saved line ends, names clear of bodies', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const d = await drawn(page);
    const bodyOf = new Map(d.bodies.map((b) => [b.name, b]));
    const portAt = new Map(d.ports.map((p) => [`${p.component}.${p.port}`, p]));

    for (const b of d.bodies) {
        const icon = appearance.types[b.type]?.icon;
        expect(icon, b.type).toBeTruthy();
        const quarter = Math.round(b.angle / 90) % 2 !== 0;
        expect(Math.abs(b.frame.x1 - b.frame.x0 - (quarter ? icon.height : icon.width)), `${b.name} width`).toBeLessThan(1.5);
        expect(Math.abs(b.frame.y1 - b.frame.y0 - (quarter ? icon.width : icon.height)), `${b.name} height`).toBeLessThan(1.5);
    }

    let ends = 0;
    for (const c of d.saved) {
        const a = portAt.get(c.from);
        const b = portAt.get(c.to);
        if (!a || !b || !bodyOf.has(c.from.split('.')[0]) || !bodyOf.has(c.to.split('.')[0])) continue;
        const first = c.points[0];
        const last = c.points[c.points.length - 1];
        const [ea, eb] = dist(a, first) + dist(b, last) <= dist(a, last) + dist(b, first) ? [first, last] : [last, first];
        expect(dist(a, ea), `${c.from} at the saved end`).toBeLessThan(1);
        expect(dist(b, eb), `${c.to} at the saved end`).toBeLessThan(1);
        ends += 2;
    }
    expect(ends).toBeGreaterThan(40);

    // no body's solid part hides another's (Hopsan's drawing puts the Mass on the cylinder's rod,
    // inside its box, and lets Tank_C touch the valve: 0.5 px); no name covers its body
    for (let i = 0; i < d.bodies.length; i++) {
        for (let j = i + 1; j < d.bodies.length; j++) {
            const [a, b] = [d.bodies[i], d.bodies[j]];
            for (const sa of a.solid) for (const sb of b.solid) expect(overlap(sa, sb), `${a.name} over ${b.name}`).toBeLessThan(20);
        }
        expect(overlap(d.bodies[i].label!, d.bodies[i].frame), `${d.bodies[i].name}'s name on its body`).toBe(0);
    }
});

test('F16systemManeuver: every line ends on its port, every port on its body', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'F16systemManeuver');
    const d = await drawn(page);
    const portAt = new Map(d.ports.map((p) => [`${p.component}.${p.port}`, p]));
    const bodyOf = new Map(d.bodies.map((b) => [b.name, b]));
    expect(d.lines.length).toBeGreaterThan(20);
    for (const line of d.lines) {
        const ends: [string, [number, number]][] = [[line.from, line.points[0]], [line.to, line.points[line.points.length - 1]]];
        for (const [ref, end] of ends) {
            const p = portAt.get(ref);
            expect(p, ref).toBeTruthy();
            expect(dist(p!, end), `${ref}: line end on the port`).toBeLessThan(1);
        }
        for (let i = 1; i < line.points.length; i++) {
            const [a, b] = [line.points[i - 1], line.points[i]];
            expect(Math.min(Math.abs(a[0] - b[0]), Math.abs(a[1] - b[1])), `${line.from}-${line.to} square`).toBeLessThan(1);
        }
    }
    let onBody = 0;
    for (const p of d.ports) {
        const body = bodyOf.get(p.component);
        if (!body || !appearance.types[body.type]) continue;
        const f = body.frame;
        const off = Math.max(f.x0 - p.x, p.x - f.x1, f.y0 - p.y, p.y - f.y1, 0);
        expect(off, `${p.component}.${p.port} off its body`).toBeLessThan(1);
        onBody++;
    }
    expect(onBody).toBeGreaterThan(20);
});
