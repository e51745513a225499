// Lines and gestures (issue 39, item 3), on Position Servo as a Hopsan user works: a line's
// segment between two corners dragged across, undone and redone, saved and found again after a
// reload; a drag on the empty canvas selects what its box holds, Space+drag and the middle
// button pan; a dragged component snaps onto another's centre line with a guide shown.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { expect, test, type Page } from './fixtures';
import { login, openExample } from './helpers';
import type { Connection, Pose, System } from '../src/protocol/types';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const SERVO = 'Position Servo';

interface Point { x: number; y: number }
interface Handle {
    store: { system: System; selection: Set<string> };
    canvas: { linePath(from: unknown, to: unknown): Point[] | null; clientFromScene(p: Point): Point; sceneFromClient(x: number, y: number): Point };
}

/** A line of the open system with a segment between two corners that is long on screen. */
async function draggableSegment(page: Page) {
    return page.evaluate(() => {
        const { store, canvas } = (window as unknown as { __tlmhub: Handle }).__tlmhub;
        for (const line of store.system.connections) {
            const path = canvas.linePath(line.from, line.to);
            if (!path) continue;
            for (let i = 1; i + 2 <= path.length - 1; i++) {
                const [a, b] = [canvas.clientFromScene(path[i]), canvas.clientFromScene(path[i + 1])];
                const horizontal = Math.abs(path[i].y - path[i + 1].y) < 0.5;
                const vertical = Math.abs(path[i].x - path[i + 1].x) < 0.5;
                const grab = { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
                // nothing drawn over the line there
                const hit = document.elementFromPoint(grab.x, grab.y)?.closest('.connection, .line-hit');
                const ours = hit?.getAttribute('data-from') === `${line.from.component}.${line.from.port}`
                    && hit?.getAttribute('data-to') === `${line.to.component}.${line.to.port}`;
                if ((horizontal || vertical) && Math.hypot(a.x - b.x, a.y - b.y) > 40 && ours) {
                    return { from: line.from, to: line.to, path, index: i, horizontal, grab };
                }
            }
        }
        return null;
    });
}

async function pointsOf(page: Page, from: Connection['from'], to: Connection['to']): Promise<[number, number][]> {
    return page.evaluate(([f, t]) => {
        const { store } = (window as unknown as { __tlmhub: Handle }).__tlmhub;
        const same = (a: { component: string; port: string }, b: { component: string; port: string }) => a.component === b.component && a.port === b.port;
        return store.system.connections.find((c) => same(c.from, f) && same(c.to, t))!.points;
    }, [from, to] as const);
}

async function save(page: Page): Promise<void> {
    await page.getByTestId('save').click();
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
}

test('a segment between corners dragged across its line is one undo step, and is saved and reloaded as drawn', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    await page.getByTestId('save').click();   // her own copy, to save the change in
    await expect(page.getByTestId('save')).toHaveText('Save');
    const grip = await draggableSegment(page);
    expect(grip, 'Position Servo has a line with a segment between two corners').not.toBeNull();
    const { from, to, path, index, horizontal } = grip!;
    const before = await pointsOf(page, from, to);

    await page.mouse.move(grip!.grab.x, grip!.grab.y);
    await page.mouse.down();
    await page.mouse.move(grip!.grab.x + 30, grip!.grab.y + 30, { steps: 6 });
    await page.mouse.up();
    // the segment moved across its own direction only; the ends stay on their ports
    const scale = await page.evaluate(() => { const c = (window as unknown as { __tlmhub: Handle }).__tlmhub.canvas; return c.clientFromScene({ x: 1, y: 0 }).x - c.clientFromScene({ x: 0, y: 0 }).x; });
    // the line takes its new points when the server has the route (a busy machine answers late)
    await expect.poll(() => pointsOf(page, from, to)).not.toEqual(before);
    const moved = await pointsOf(page, from, to);
    expect(moved[0]).toEqual([path[0].x, path[0].y]);
    expect(moved[moved.length - 1]).toEqual([path[path.length - 1].x, path[path.length - 1].y]);
    const shift = 30 / scale;
    const expected = [path[index], path[index + 1]].map((p) => (horizontal ? [p.x, Math.round(p.y + shift)] : [Math.round(p.x + shift), p.y]));
    expect(moved).toContainEqual(expected[0]);
    expect(moved).toContainEqual(expected[1]);
    await expect(page.locator('.line-corner').first()).toBeVisible();   // the selected line shows its corners
    mkdirSync(screenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}line-segment-dragged.png` });

    await page.keyboard.press('Control+z');
    await expect.poll(() => pointsOf(page, from, to)).toEqual(before);
    await page.keyboard.press('Control+y');
    await expect.poll(() => pointsOf(page, from, to)).toEqual(moved);

    await save(page);
    await page.reload();
    await expect(page.locator('.canvas .component').first()).toBeVisible();
    await expect.poll(() => pointsOf(page, from, to)).toEqual(moved);
    const drawn = await page.locator(`.canvas .connection[data-from="${from.component}.${from.port}"][data-to="${to.component}.${to.port}"]`).getAttribute('points');
    expect(drawn).toContain(`${expected[0][0]},${expected[0][1]}`);
});

test('a drag on the empty canvas selects the components in its box; Space+drag and the middle button pan instead', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const canvasBox = (await page.getByTestId('canvas').boundingBox())!;
    // from the top-left corner of the canvas, which the fitted drawing leaves empty, to its middle
    const start = { x: canvasBox.x + 6, y: canvasBox.y + 6 };
    const end = { x: canvasBox.x + canvasBox.width / 2, y: canvasBox.y + canvasBox.height / 2 };
    const expected = await page.evaluate(([a, b]) => {
        const { store, canvas } = (window as unknown as { __tlmhub: Handle }).__tlmhub;
        const [p, q] = [canvas.sceneFromClient(a.x, a.y), canvas.sceneFromClient(b.x, b.y)];
        return store.system.components.filter((c) => c.pose.x >= p.x && c.pose.x <= q.x && c.pose.y >= p.y && c.pose.y <= q.y).map((c) => c.name).sort();
    }, [start, end] as const);
    expect(expected.length, 'the box holds some of the components').toBeGreaterThan(0);
    await page.mouse.move(start.x, start.y);
    await page.mouse.down();
    await page.mouse.move(end.x, end.y, { steps: 8 });
    await expect(page.locator('.canvas .marquee')).toBeVisible();
    await page.mouse.up();
    const selected = () => page.evaluate(() => [...(window as unknown as { __tlmhub: Handle }).__tlmhub.store.selection].sort());
    expect(await selected()).toEqual(expected);

    const transform = () => page.locator('.canvas .world').getAttribute('transform');
    const translation = async () => (await transform())!.match(/translate\(([-\d.e]+),([-\d.e]+)\)/)!.slice(1).map(Number);
    const [tx, ty] = await translation();
    await page.keyboard.down(' ');
    await page.mouse.move(start.x, start.y);
    await page.mouse.down();
    await page.mouse.move(start.x + 50, start.y + 40, { steps: 5 });
    await page.mouse.up();
    await page.keyboard.up(' ');
    expect(await translation()).toEqual([tx + 50, ty + 40]);
    expect(await selected()).toEqual(expected);   // a pan, not a new box

    await page.mouse.move(end.x, end.y);
    await page.mouse.down({ button: 'middle' });
    await page.mouse.move(end.x - 30, end.y - 20, { steps: 5 });
    await page.mouse.up({ button: 'middle' });
    expect(await translation()).toEqual([tx + 20, ty + 20]);
    expect(await selected()).toEqual(expected);
});

test('a component dragged near another\'s centre line snaps onto it and shows the guide meanwhile', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    // Step, and a component well away from it whose centre line no third one comes near
    const plan = await page.evaluate(() => {
        const { store, canvas } = (window as unknown as { __tlmhub: Handle }).__tlmhub;
        const components = store.system.components;
        const step = components.find((c) => c.name === 'Step')!;
        const alone = (x: number) => components.every((c) => c === step || c.pose.x === x || Math.abs(c.pose.x - x) > 12);
        const other = components.find((c) => Math.abs(c.pose.x - step.pose.x) > 80 && Math.abs(c.pose.y - step.pose.y) > 40 && alone(c.pose.x))!;
        return { step: step.pose as Pose, other: { name: other.name, pose: other.pose as Pose },
            grab: canvas.clientFromScene({ x: step.pose.x, y: step.pose.y }), target: canvas.clientFromScene({ x: other.pose.x, y: step.pose.y }) };
    });
    await page.mouse.move(plan.grab.x, plan.grab.y);
    await page.mouse.down();
    // to 3 pixels short of the other's vertical centre line, with a little vertical drift
    await page.mouse.move(plan.target.x - 3, plan.target.y + 2, { steps: 10 });
    // (a guide is a line, which has no area: counted, not checked for visibility)
    await expect(page.locator('.canvas .alignment-guide[data-axis="x"]')).toHaveCount(1);
    mkdirSync(screenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}alignment-guide.png` });
    await page.mouse.up();
    await expect(page.locator('.canvas .alignment-guide')).toHaveCount(0);
    // the move is the model's when the server has it
    const stepX = () => page.evaluate(() => (window as unknown as { __tlmhub: Handle }).__tlmhub.store.system.components.find((c) => c.name === 'Step')!.pose.x);
    await expect.poll(stepX).toBe(plan.other.pose.x);
});
