// @vitest-environment jsdom
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { LABEL_GAP, bodyBox, labelAt, overlaps, placeLabels, type Box, type Labelled } from './labelPlacement';
import { appearanceOf } from '../model/appearance';

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
});

// (the jsdom environment gives import.meta.url no file: scheme; tests run from web/)
const examples = `${resolve(process.cwd(), '../../shared')}/hopsan-models/Example Models/`;

/** The top-level components of an example model with their icon size from appearance.json. */
function components(file: string): Labelled[] {
    const doc = new DOMParser().parseFromString(readFileSync(`${examples}${file}`, 'utf8'), 'application/xml');
    const objects = doc.querySelector('hopsanmodelfile > system > objects')!;
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
