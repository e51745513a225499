// @vitest-environment jsdom
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { LABEL_GAP, bodyBox, labelAt, overlaps, placeLabels, segmentCrosses, type Box, type Labelled, type Polyline } from './labelPlacement';
import { appearanceOf } from '../model/appearance';
import type { Point } from '../model/geometry';

describe('component name placement', () => {
    const layout = { halfWidth: 80, halfHeight: 25 };
    const pose = { x: 0, y: 0, angle: 0, flipped: false };

    it('sits above the body, upright, whatever the rotation', () => {
        const above = placeLabels([{ name: 'A', pose, layout }]).get('A')!;
        expect(above.box.y1).toBe(-25 - LABEL_GAP);
        expect(above.x).toBe(0);
        const turned = placeLabels([{ name: 'A', pose: { x: 10, y: 20, angle: 90, flipped: true }, layout }]).get('A')!;
        expect(turned.x).toBeCloseTo(10, 9);
        expect(turned.box.y1).toBeCloseTo(20 - 80 - LABEL_GAP, 9);
    });

    it('goes below, then left, then right when the spot above is taken', () => {
        const small = { halfWidth: 10, halfHeight: 10 };
        // a body right above A, then one right below, then one to the left
        const a = { name: 'A', pose, layout: small };
        const blocker = (name: string, x: number, y: number): Labelled => ({ name, pose: { ...pose, x, y }, layout: small });
        expect(placeLabels([blocker('N', 0, -24), a]).get('A')!.side).toBe('below');
        expect(placeLabels([blocker('N', 0, -24), blocker('S', 0, 26), a]).get('A')!.side).toBe('left');
        expect(placeLabels([blocker('N', 0, -24), blocker('S', 0, 26), blocker('W', -24, 0), a]).get('A')!.side).toBe('right');
        // nowhere free: above, as by default
        const boxed = [blocker('N', 0, -24), blocker('S', 0, 26), blocker('W', -24, 0), blocker('E', 24, 0), a];
        expect(placeLabels(boxed).get('A')!.side).toBe('above');
    });

    const small = { halfWidth: 10, halfHeight: 10 };
    const a = { name: 'Alpha', pose, layout: small };
    // the name's text box on each side of A (10 px text: y -20..-10 above, 14..24 below, x -20 and 20 beside)
    const horizontal = (y: number): Polyline => [{ x: -100, y }, { x: 100, y }];
    const vertical = (x: number): Polyline => [{ x, y: -100 }, { x, y: 100 }];

    it('moves off a connection line crossing the spot above', () => {
        expect(placeLabels([a], [horizontal(-17)]).get('Alpha')!.side).toBe('below');
        // a line elsewhere, or one ending short of the name, changes nothing
        expect(placeLabels([a], [horizontal(-60), [{ x: -100, y: -17 }, { x: -40, y: -17 }]]).get('Alpha')!.side).toBe('above');
        // above and below crossed: left; then right
        expect(placeLabels([a], [horizontal(-17), horizontal(17)]).get('Alpha')!.side).toBe('left');
        expect(placeLabels([a], [horizontal(-17), horizontal(17), vertical(-25)]).get('Alpha')!.side).toBe('right');
    });

    it('stays above when every side is crossed as often, and takes the side crossed least', () => {
        const everySide = [horizontal(-17), horizontal(17), vertical(-25), vertical(25)];
        expect(placeLabels([a], everySide).get('Alpha')!.side).toBe('above');
        // two lines above, one on each other side: below
        expect(placeLabels([a], [...everySide, horizontal(-15)]).get('Alpha')!.side).toBe('below');
        // a polyline counts once however many of its segments cross
        const zigzag: Polyline = [{ x: -100, y: -17 }, { x: -5, y: -17 }, { x: -5, y: -14 }, { x: 100, y: -14 }];
        expect(placeLabels([a], [zigzag, horizontal(17), horizontal(18), vertical(-25), vertical(25)]).get('Alpha')!.side).toBe('above');
    });

    it('still keeps a name off other names and bodies before avoiding lines', () => {
        const blocker: Labelled = { name: 'N', pose: { ...pose, y: 26 }, layout: small };
        // above crossed, below covers a body: left, not below
        expect(placeLabels([blocker, a], [horizontal(-17)]).get('Alpha')!.side).toBe('left');
    });

    it('counts a slanted segment only where it passes through the box', () => {
        const box = { x0: 0, y0: 0, x1: 10, y1: 10 };
        expect(segmentCrosses({ x: -5, y: 3 }, { x: 5, y: 13 }, box)).toBe(true);
        // its bounding box overlaps the box's corner, the segment itself does not
        expect(segmentCrosses({ x: -5, y: 8 }, { x: 8, y: 21 }, box)).toBe(false);
        expect(segmentCrosses({ x: 2, y: 2 }, { x: 3, y: 4 }, box)).toBe(true);
        // along an edge is not through
        expect(segmentCrosses({ x: -5, y: 0 }, { x: 15, y: 0 }, box)).toBe(false);
    });
});

// (the jsdom environment gives import.meta.url no file: scheme; tests run from web/)
const examples = `${resolve(process.cwd(), '../../shared')}/hopsan-models/Example Models/`;

const TOP = 'hopsanmodelfile > system';
const parsed = new Map<string, Document>();
const parse = (file: string): Document => {
    if (!parsed.has(file)) parsed.set(file, new DOMParser().parseFromString(readFileSync(`${examples}${file}`, 'utf8'), 'application/xml'));
    return parsed.get(file)!;
};

/** The components of a system of an example model (the top level by default) with their icon size from appearance.json. */
function components(file: string, system = TOP): Labelled[] {
    const objects = parse(file).querySelector(`${system} > objects`)!;
    return [...objects.children].filter((el) => el.tagName === 'component' || el.tagName === 'system').map((el) => {
        const p = el.querySelector(':scope > hopsangui > pose')!;
        const facts = appearanceOf(el.getAttribute('typename')!);
        return {
            name: el.getAttribute('name')!,
            pose: { x: Number(p.getAttribute('x')), y: Number(p.getAttribute('y')), angle: Number(p.getAttribute('a')), flipped: p.getAttribute('flipped') === 'true' },
            layout: facts ? { halfWidth: facts.width / 2, halfHeight: facts.height / 2 } : { halfWidth: 20, halfHeight: 20 },
        };
    });
}

/** The connection lines of a system of an example model as saved. */
function lines(file: string, system = TOP): Polyline[] {
    const connections = parse(file).querySelector(`${system} > connections`);
    return [...(connections?.children ?? [])].filter((el) => el.tagName === 'connect').map((el) =>
        [...el.querySelectorAll(':scope > hopsangui > coordinates > coordinate')].map((c) => ({ x: Number(c.getAttribute('x')), y: Number(c.getAttribute('y')) })));
}

/** Names with a connection line through them (points every 0.25 px along each line, apart from the placement's own test). */
function crossedNames(labels: Box[], drawn: Polyline[]): number {
    const inside = (x: number, y: number, b: Box) => x > b.x0 && x < b.x1 && y > b.y0 && y < b.y1;
    const through = (box: Box, a: Point, b: Point) => {
        const steps = Math.ceil(Math.hypot(b.x - a.x, b.y - a.y) * 4);
        for (let k = 0; k <= steps; k++) if (inside(a.x + ((b.x - a.x) * k) / steps, a.y + ((b.y - a.y) * k) / steps, box)) return true;
        return false;
    };
    return labels.filter((box) => drawn.some((line) => line.some((p, k) => k > 0 && through(box, line[k - 1], p)))).length;
}

function labelOverlaps(boxes: Box[]): number {
    let n = 0;
    for (let i = 0; i < boxes.length; i++) for (let j = i + 1; j < boxes.length; j++) if (overlaps(boxes[i], boxes[j])) n++;
    return n;
}

/** Names over another component's body. */
function bodyOverlaps(labels: Box[], bodies: Box[]): number {
    return labels.reduce((n, label, i) => n + bodies.filter((body, j) => j !== i && overlaps(label, body)).length, 0);
}

describe('names on the example models', () => {
    // name-name overlaps with every name above (the former rule), then as placed
    for (const [file, before, after] of [['Position Servo.hmf', 0, 0], ['Load Sensing System.hmf', 10, 1]] as const) {
        it(`${file}: names over names ${before} -> ${after}, and no more names over bodies`, () => {
            const items = components(file);
            const bodies = items.map((item) => bodyBox(item.pose, item.layout));
            const allAbove = items.map((item, i) => labelAt('above', bodies[i], item.name).box);
            const placed = [...placeLabels(items).values()].map((spot) => spot.box);
            console.log(`${file}: names over names ${labelOverlaps(allAbove)} -> ${labelOverlaps(placed)}, `
                + `names over other bodies ${bodyOverlaps(allAbove, bodies)} -> ${bodyOverlaps(placed, bodies)}`);
            expect(labelOverlaps(allAbove)).toBe(before);
            expect(labelOverlaps(placed)).toBe(after);
            expect(bodyOverlaps(placed, bodies)).toBeLessThanOrEqual(bodyOverlaps(allAbove, bodies));
        });
    }
});

describe('names off the connection lines of the example models', () => {
    // names crossed by a line when placement ignores the lines (the former rule), then as placed
    for (const [file, before, after] of [['Position Servo.hmf', 10, 1], ['Load Sensing System.hmf', 27, 11]] as const) {
        it(`${file}: names crossed by lines ${before} -> ${after}, no more names over names or bodies`, () => {
            const items = components(file);
            const drawn = lines(file);
            const bodies = items.map((item) => bodyBox(item.pose, item.layout));
            const ignoring = [...placeLabels(items).values()].map((spot) => spot.box);
            const placed = [...placeLabels(items, drawn).values()].map((spot) => spot.box);
            console.log(`${file}: ${items.length} names, ${drawn.length} lines; names crossed by lines ${crossedNames(ignoring, drawn)} -> ${crossedNames(placed, drawn)}; `
                + `names over names ${labelOverlaps(ignoring)} -> ${labelOverlaps(placed)}, over other bodies ${bodyOverlaps(ignoring, bodies)} -> ${bodyOverlaps(placed, bodies)}`);
            expect(crossedNames(ignoring, drawn)).toBe(before);
            expect(crossedNames(placed, drawn)).toBe(after);
            expect(labelOverlaps(placed)).toBeLessThanOrEqual(labelOverlaps(ignoring));
            expect(bodyOverlaps(placed, bodies)).toBeLessThanOrEqual(bodyOverlaps(ignoring, bodies));
        });
    }

    it('F16systemManeuver: placing the names of all its systems among their lines stays fast', () => {
        const doc = parse('F16systemManeuver.hmf');
        // every system of the model by its path of names, each with its own names and lines
        const paths = [...doc.querySelectorAll('system')].map((el) => {
            const names: string[] = [];
            for (let e: Element | null = el; e && e.tagName === 'system'; e = e.parentElement?.parentElement ?? null) names.unshift(e.getAttribute('name')!);
            return [TOP, ...names.slice(1).map((n) => `objects > system[name="${n}"]`)].join(' > ');
        });
        const systems = paths.map((path) => ({ items: components('F16systemManeuver.hmf', path), drawn: lines('F16systemManeuver.hmf', path) }));
        const place = (withLines: boolean) => {
            const t0 = performance.now();
            for (let i = 0; i < 10; i++) for (const { items, drawn } of systems) placeLabels(items, withLines ? drawn : []);
            return (performance.now() - t0) / 10;
        };
        for (let i = 0; i < 3; i++) { place(false); place(true); }
        const [without, among] = [place(false), place(true)];
        const names = systems.reduce((n, sys) => n + sys.items.length, 0);
        const count = systems.reduce((n, sys) => n + sys.drawn.length, 0);
        console.log(`F16systemManeuver: ${names} names in ${systems.length} systems among ${count} lines placed in ${among.toFixed(2)} ms (${without.toFixed(2)} ms ignoring the lines)`);
        expect(names).toBeGreaterThan(100);
    }, 60_000);
});
