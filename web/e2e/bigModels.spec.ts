// Issue 13.9 and 13.10: timings on the big examples (measured and reported, not asserted)
// and the screenshots of the docs.
import { mkdirSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect, type Page } from './fixtures';
import { login, openExample } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));
const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const timings: Record<string, number> = {};

function report(name: string, ms: number): void {
    timings[name] = Math.round(ms * 10) / 10;
    test.info().annotations.push({ type: 'timing', description: `${name}: ${timings[name]} ms` });
    console.log(`timing ${name}: ${timings[name]} ms`);
    mkdirSync(screenshots, { recursive: true });
    writeFileSync(`${screenshots}timings.json`, JSON.stringify(timings, null, 2));
}

/** The browser's main-thread work (script, style, layout) while `work` runs, from Chromium's own counters. */
async function mainThreadWork<T>(page: Page, work: () => Promise<T>): Promise<{ result: T; script: number; layout: number }> {
    const cdp = await page.context().newCDPSession(page);
    await cdp.send('Performance.enable');
    const metrics = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
    const before = await metrics();
    const result = await work();
    const after = await metrics();
    await cdp.detach();
    const ms = (key: string) => (after[key] - before[key]) * 1000;
    return { result, script: ms('ScriptDuration'), layout: ms('LayoutDuration') + ms('RecalcStyleDuration') };
}

/**
 * Median time of the page's own work for `step` on the open model (its render and the layout
 * of what it drew), without network or browser round trips.
 */
async function pageWork(page: Page, step: 'redraw' | 'select' | 'enter'): Promise<number> {
    return page.evaluate((which) => {
        type Store = { model: unknown; path: string[]; system: { components: { name: string; system?: unknown }[] };
            replaceModel(m: unknown): void; select(n: string[]): void; enterSystem(p: string[]): void };
        const store = (window as unknown as { __tlmhub: { store: Store } }).__tlmhub.store;
        const world = document.querySelector('svg.canvas .world')!;
        const names = store.system.components.map((c) => c.name);
        const sub = store.system.components.find((c) => c.system)!.name;
        const times: number[] = [];
        for (let i = 0; i < 7; i++) {
            const t0 = performance.now();
            if (which === 'redraw') store.replaceModel(store.model);
            else if (which === 'select') store.select([names[i % names.length]]);
            else store.enterSystem([sub]);
            void world.getBoundingClientRect().width;
            times.push(performance.now() - t0);
            if (which === 'enter') {
                store.enterSystem([]);
                void world.getBoundingClientRect().width;
            }
        }
        store.select([]);
        times.sort((a, b) => a - b);
        return times[3];
    }, step);
}

async function openTimed(page: Page, name: string): Promise<number> {
    const row = page.getByTestId('example-models').locator('tr', { has: page.getByRole('link', { name, exact: true }) });
    const t0 = Date.now();
    await row.getByRole('button', { name: 'Open' }).click();
    await expect(page.getByTestId('model-name')).toHaveText(name);
    await expect(page.locator('.canvas .component').first()).toBeVisible();
    return Date.now() - t0;
}

test.beforeAll(() => mkdirSync(docsScreenshots, { recursive: true }));

test('Position Servo and Load Sensing System as drawn; dragging in Load Sensing System', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    await page.screenshot({ path: `${docsScreenshots}position-servo.png` });

    await page.getByRole('link', { name: 'Models' }).first().click().catch(() => page.goBack());
    await expect(page.getByRole('heading', { name: 'Examples' })).toBeVisible();
    await openTimed(page, 'Load Sensing System');
    await page.screenshot({ path: `${docsScreenshots}load-sensing-system.png` });

    // time the page's own work per pointer move of a component drag (no browser round trips)
    const perMove = await page.evaluate(async () => {
        const frame = document.querySelector('.canvas .component:not(.system-port) .icon-frame') as SVGElement;
        const svg = document.querySelector('svg.canvas') as SVGSVGElement;
        const r = frame.getBoundingClientRect();
        const at = (dx: number) => ({ clientX: r.x + r.width / 2 + dx, clientY: r.y + r.height / 2, bubbles: true, pointerId: 1, button: 0, buttons: 1, isPrimary: true });
        frame.dispatchEvent(new PointerEvent('pointerdown', at(0)));
        const times: number[] = [];
        for (let i = 1; i <= 60; i++) {
            const t0 = performance.now();
            svg.dispatchEvent(new PointerEvent('pointermove', at(i)));
            // include style and layout of what the move changed
            void svg.getBoundingClientRect().width;
            document.body.offsetHeight;
            times.push(performance.now() - t0);
        }
        const name = frame.closest('.component')!.getAttribute('data-name');
        const shift = (document.querySelector(`.canvas .component[data-name="${name}"] .icon-frame`) as SVGElement).getBoundingClientRect().x - r.x;
        svg.dispatchEvent(new PointerEvent('pointerup', at(60)));
        times.sort((a, b) => a - b);
        return { median: times[30], worst: times[59], shift };
    });
    // the drag did move the component along with the pointer
    expect(perMove.shift).toBeGreaterThan(40);
    report('Load Sensing System drag, median per move', perMove.median);
    report('Load Sensing System drag, worst move', perMove.worst);
});

test('F16systemManeuver: open, enter its subsystem, the aircraft block close up', async ({ page }) => {
    await login(page, 'alice');
    const open = await mainThreadWork(page, () => openTimed(page, 'F16systemManeuver'));
    report('open F16systemManeuver', open.result);
    report('open F16systemManeuver, script', open.script);
    report('open F16systemManeuver, style and layout', open.layout);
    report('F16 page work: draw the whole model afresh (median)', await pageWork(page, 'redraw'));
    report('F16 page work: select a component (median)', await pageWork(page, 'select'));
    report('F16 page work: enter the subsystem (median)', await pageWork(page, 'enter'));
    const aircraft = page.locator('.canvas .component[data-name="AeroAircraft6DOFSS"]');
    await expect(aircraft).toBeVisible();
    // zoom in on the aircraft block with the wheel, as a user would
    const far = (await aircraft.boundingBox())!;
    await page.mouse.move(far.x + far.width / 2, far.y + far.height / 2);
    for (let i = 0; i < 4; i++) {
        await page.mouse.wheel(0, -240);
        await page.waitForTimeout(100);
    }
    const box = (await aircraft.boundingBox())!;
    // the block with some of its surroundings, inside the canvas
    const canvas = (await page.getByTestId('canvas').boundingBox())!;
    const pad = 120;
    const x = Math.max(canvas.x, box.x - pad);
    const y = Math.max(canvas.y, box.y - pad);
    await page.screenshot({
        path: `${docsScreenshots}f16-aircraft-close-up.png`,
        clip: { x, y, width: Math.min(canvas.x + canvas.width, box.x + box.width + pad) - x, height: Math.min(canvas.y + canvas.height, box.y + box.height + pad) - y },
    });

    // back out to the whole model (the same wheel steps reversed), where the subsystem is in view
    for (let i = 0; i < 4; i++) {
        await page.mouse.wheel(0, 240);
        await page.waitForTimeout(100);
    }
    const enter = await mainThreadWork(page, async () => {
        const t0 = Date.now();
        await page.locator('.canvas .component[data-name="Subsystem"] .icon-frame').dblclick();
        await expect(page.locator('.breadcrumb')).toContainText('Subsystem');
        await expect(page.locator('.canvas .component[data-name="Gearbox_driven_pump_A"]')).toBeVisible();
        return Date.now() - t0;
    });
    report('enter the F16 subsystem (double-click to drawn)', enter.result);
    report('enter the F16 subsystem, script', enter.script);
    report('enter the F16 subsystem, style and layout', enter.layout);
});
