// Issue 42 items 4 and 5: the animated diagram and the playback of a run of the history.
// Position Servo: scrubbing moves the cylinder's rod as the run's positions say and moves the
// plots' cursor; playing advances it. Load Sensing System: the draw time of a frame is
// measured and reported (not asserted beyond a loose sanity bound), and the docs' screenshots.
import { fileURLToPath } from 'node:url';
import { test, expect, type Page } from './fixtures';
import { login, openExample, plotVariable, runAndWait } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

const shiftOf = (transform: string | null) => Number(/translate\(([-\d.]+)/.exec(transform ?? '')?.[1] ?? NaN);
const cursorX = async (page: Page) =>
    Number(/translateX\(([-\d.]+)px\)/.exec(await page.getByTestId('playback-cursor').first().evaluate((el) => (el as HTMLElement).style.transform))?.[1] ?? NaN);

/** Starts playback of run `job` from its row in the history. */
async function playBack(page: Page, job: number): Promise<void> {
    await page.locator(`.history-row[data-job="${job}"] .history-play`).click();
    await expect(page.getByTestId('playback-bar')).toBeVisible();
    await expect(page.getByTestId('pressure-scale')).toBeVisible();
}

/** The run's value of `name` at the playback's time, interpolated as the diagram does. */
async function valueAtPlayback(page: Page, name: string): Promise<number> {
    return page.evaluate((n) => {
        type Run = { time: number[]; columns: Map<string, number[]> };
        const app = (window as unknown as { __tlmhub: { playback: { time: number; shownRun: Run } } }).__tlmhub;
        const { time, columns } = app.playback.shownRun;
        const column = columns.get(n)!;
        const t = app.playback.time;
        let i = 0;
        while (i + 1 < time.length && time[i + 1] <= t) i++;
        if (i + 1 >= time.length) return column[i];
        return column[i] + ((column[i + 1] - column[i]) * (t - time[i])) / (time[i + 1] - time[i]);
    }, name);
}

/**
 * performance.now() around the diagram's show() over many frames of the played-back run (each
 * sample's values), also with the style and layout it causes; reported, bound only loosely.
 */
async function measureDraw(page: Page, model: string): Promise<void> {
    const timing = await page.evaluate(async () => {
        type Run = { time: number[]; columns: Map<string, number[]> };
        type App = { playback: { shownRun: Run }; animation: { variables(): string[]; show(v: ReadonlyMap<string, number>): void } };
        const app = (window as unknown as { __tlmhub: App }).__tlmhub;
        const run = app.playback.shownRun;
        const names = app.animation.variables().filter((n) => run.columns.has(n));
        const frames = 300;
        const show: number[] = [];
        const withLayout: number[] = [];
        const world = document.querySelector('svg.canvas .world')!;
        for (let f = 0; f < frames; f++) {
            const i = Math.floor((f * (run.time.length - 1)) / (frames - 1));
            const values = new Map(names.map((n) => [n, run.columns.get(n)![i]]));
            const t0 = performance.now();
            app.animation.show(values);
            const t1 = performance.now();
            void world.getBoundingClientRect().width;
            withLayout.push(performance.now() - t0);
            show.push(t1 - t0);
            if (f % 30 === 0) await new Promise(requestAnimationFrame);
        }
        const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[xs.length >> 1];
        return { variables: names.length, show: median(show), showMax: Math.max(...show), layout: median(withLayout), layoutMax: Math.max(...withLayout),
            slowest: withLayout.map((ms, f) => [f, Math.round(ms)]).filter(([, ms]) => ms > 16) };
    });
    const text = `${model}: ${timing.variables} variables; show() median ${timing.show.toFixed(2)} ms (max ${timing.showMax.toFixed(2)}), `
        + `with style and layout median ${timing.layout.toFixed(2)} ms (max ${timing.layoutMax.toFixed(2)}); frames over 16 ms [frame, ms]: ${JSON.stringify(timing.slowest)}`;
    // while playing at 10×: the time between the browser's frames, which includes painting
    const frames = await page.evaluate(async () => {
        const app = (window as unknown as { __tlmhub: { playback: { play(): void; pause(): void } } }).__tlmhub;
        const stamps: number[] = [];
        document.querySelector<HTMLSelectElement>('[data-testid="playback-speed"]')!.value = '10';
        app.playback.play();
        const until = performance.now() + 1500;
        while (performance.now() < until) stamps.push(await new Promise<number>(requestAnimationFrame));
        app.playback.pause();
        const gaps = stamps.slice(1).map((t, i) => t - stamps[i]).sort((a, b) => a - b);
        return { median: gaps[gaps.length >> 1], p95: gaps[Math.floor(gaps.length * 0.95)] };
    });
    const playing = `; playing at 10×: frame interval median ${frames.median.toFixed(1)} ms, 95th percentile ${frames.p95.toFixed(1)} ms`;
    test.info().annotations.push({ type: 'timing', description: text + playing });
    console.log(text + playing);
    expect(timing.layout).toBeLessThan(200);
}

test('plays back a Position Servo run: the rod moves as its positions say, the plot cursor follows', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const position = await plotVariable(page, 'Cylinder_C', 'P3', 'Position');
    const job = await runAndWait(page);
    await playBack(page, job);

    const rod = page.locator('.component[data-name="Cylinder_C"] .animation-parts .movable-part');
    await expect(rod).toHaveCount(1);
    const slider = page.getByTestId('playback-slider');
    const strokeLength = await page.evaluate(() => {
        type Store = { system: { components: { name: string; parameters: { name: string; value: string }[] }[] } };
        const store = (window as unknown as { __tlmhub: { store: Store } }).__tlmhub.store;
        return Number(store.system.components.find((c) => c.name === 'Cylinder_C')!.parameters.find((p) => p.name === 's_l#Value')!.value);
    });

    // two instants: the rod's shift between them is the run's position change, 77.5 icon px per stroke length
    await slider.fill('100');
    await expect(page.getByTestId('playback-time')).toContainText('0.150 s');
    const [x1, shift1, cursor1] = [await valueAtPlayback(page, position), shiftOf(await rod.getAttribute('transform')), await cursorX(page)];
    await slider.fill('1600');
    await expect(page.getByTestId('playback-time')).toContainText('2.400 s');
    const [x2, shift2, cursor2] = [await valueAtPlayback(page, position), shiftOf(await rod.getAttribute('transform')), await cursorX(page)];
    expect(Math.abs(x2 - x1)).toBeGreaterThan(0.01);
    // (Hopsan's rule: rest less movement times value; P3 runs from 0 to −s_l as the rod goes out)
    expect(shift2 - shift1).toBeCloseTo((-77.5 * (x2 - x1)) / strokeLength, 1);
    expect(cursor2).toBeGreaterThan(cursor1 + 50);
    await expect(page.getByTestId('playback-cursor').first()).toHaveAttribute('data-time', /^2\.4/);

    // lines are coloured by pressure
    const colours = await page.locator('.animation-lines .animated-line').evaluateAll((els) => new Set(els.map((e) => e.getAttribute('stroke'))).size);
    expect(colours).toBeGreaterThan(2);

    await page.getByTestId('playback-slider').fill('400');
    await page.getByTestId('playback-speed').selectOption('0.5');
    await page.screenshot({ path: `${docsScreenshots}playback-timeline.png` });
    // playing moves the time, the slider and the cursor on
    const before = await cursorX(page);
    await page.getByTestId('playback-play').click();
    await expect.poll(() => cursorX(page), { timeout: 10_000 }).toBeGreaterThan(before + 5);
    await expect.poll(async () => Number(await slider.inputValue())).toBeGreaterThan(400);
    await page.getByTestId('playback-play').click();   // pause

    await measureDraw(page, 'Position Servo');

    // leaving playback gives the drawing back to the editor
    await page.getByTestId('playback-close').click();
    await expect(page.locator('.animation-lines, .animation-parts, [data-testid="pressure-scale"]')).toHaveCount(0);
    await expect(page.locator('.canvas .connection[style*="hidden"], .canvas .icon [style*="hidden"]')).toHaveCount(0);
    await expect(page.getByTestId('playback-cursor').first()).toBeHidden();
});

test('plays back a Load Sensing System run; the draw time of a frame is measured', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Load Sensing System');
    const job = await runAndWait(page);
    await playBack(page, job);
    await expect(page.locator('.animation-parts').first()).toBeAttached();

    await measureDraw(page, 'Load Sensing System');

    // mid-run, coloured lines and the scale (the docs' screenshot), on a larger page
    await page.setViewportSize({ width: 1600, height: 1300 });
    await page.getByRole('button', { name: 'Fit' }).click();
    await page.getByTestId('playback-slider').fill('1000');
    await expect(page.getByTestId('playback-time')).toContainText('15.000 s');
    await page.locator('.canvas-wrap').screenshot({ path: `${docsScreenshots}load-sensing-system-animated.png` });
});

test('playing back Sub System Example, the drawing inside a subsystem entered animates too', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Sub System Example');
    const job = await runAndWait(page);
    await playBack(page, job);
    await page.getByTestId('playback-slider').fill('1000');
    await page.locator('.canvas .component[data-name="Servo1"] .icon-frame').dblclick();
    await expect(page.locator('.breadcrumb')).toContainText('Servo1');
    // the subsystem's values are loaded and drawn: its cylinder's rod is out of its rest place
    await expect.poll(() => page.evaluate(() => {
        const app = (window as unknown as { __tlmhub: { playback: { shownRun: { columns: Map<string, number[]> } } } }).__tlmhub;
        return app.playback.shownRun.columns.has('Servo1$Cylinder_C#P3#Position');
    })).toBe(true);
    const rod = page.locator('.component[data-name="Cylinder_C"] .animation-parts .movable-part');
    const restShift = await page.evaluate(() => {
        const barrel = document.querySelector('.component[data-name="Cylinder_C"] .glyph-barrel')!;
        const piston = document.querySelector('.component[data-name="Cylinder_C"] .icon > .glyph-piston')!;
        const n = (el: Element, a: string) => Number(el.getAttribute(a));
        return n(barrel, 'x') + Math.max(0.8, n(barrel, 'stroke-width')) - n(piston, 'x');
    });
    await expect.poll(async () => Math.abs(shiftOf(await rod.getAttribute('transform')) - restShift)).toBeGreaterThan(1);
    await expect(page.locator('.animation-lines .animated-line').first()).toBeAttached();
});
