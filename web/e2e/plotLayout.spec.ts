// Issue 38 item 5, layout: a splitter between the drawing and the plots; a plot window that is
// maximised or detached into a browser window of its own (still streaming); a compact legend
// that leaves the graph its height with 40 curves; a fifth unit asks where it goes; two cursors
// with Δt and Δvalue.
import { fileURLToPath } from 'node:url';
import { test, expect, type Page } from './fixtures';
import { login, openExample, plotVariable, runAndWait, setRunField } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

/** ElectricVehicle ports whose 12 variables (V, A, rad/s, Nm) go in one plot window. */
const VEHICLE: [string, string, string][] = [
    ['ElectricBattery', 'Pel1', 'Voltage'],
    ['ElectricCapacitance2', 'Pel2', 'Voltage'],
    ['ElectricCapacitance2_1', 'Pel2', 'Voltage'],
    ['ElectricBattery', 'Pel1', 'Current'],
    ['ElectricMotorGear', 'Pel1', 'Current'],
    ['ElectricIcontroller', 'Pel1', 'Current'],
    ['ElectricCapacitance2', 'Pel1', 'Current'],
    ['MechanicRotShaft', 'Pmr1', 'AngularVelocity'],
    ['MechanicVehicle1D', 'Pmr1', 'AngularVelocity'],
    ['MechanicRotShaft', 'Pmr1', 'Torque'],
    ['MechanicVehicle1D', 'Pmr1', 'Torque'],
    ['ElectricMotorGear', 'Pmr1', 'Torque'],
];

const windowOf = (page: Page, i = 0) => page.locator('.plot-window').nth(i);
const heightOf = async (page: Page, selector: string) => (await page.locator(selector).first().boundingBox())!.height;

/** Variables of the open model's ports of the given node types, as a click on a port would add them, through the test handle. */
async function addPortVariables(page: Page, wanted: Record<string, [string, string][]>, count: number): Promise<string[]> {
    return page.evaluate(([types, n]) => {
        const app = (window as unknown as { __tlmhub: {
            store: { model: { system: { components: { name: string; ports: { name: string; node_type: string; multiport?: boolean }[] }[] } } };
            plots: { addVariable(name: string, label: string, unit: string): void } } }).__tlmhub;
        const names: string[] = [];
        for (const c of app.store.model.system.components) {
            for (const p of c.ports) {
                for (const [variable, unit] of types[p.node_type] ?? []) {
                    if (p.multiport || names.length >= n) continue;
                    const name = `${c.name}#${p.name}#${variable}`;
                    app.plots.addVariable(name, `${c.name}.${p.name} ${variable}`, unit);
                    names.push(name);
                }
            }
        }
        return names;
    }, [wanted, count] as const);
}

test('the splitter shares the height between drawing and plots, by mouse and keys, and is remembered', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const splitter = page.getByRole('separator', { name: 'Resize the drawing and the plots' });
    await expect(splitter).toBeVisible();
    const before = { run: await heightOf(page, '.run-area'), drawing: await heightOf(page, '.canvas-column') };
    const share = Number(await splitter.getAttribute('aria-valuenow'));

    // dragged 150 px up: the run area gains what the drawing loses
    const bar = (await splitter.boundingBox())!;
    await page.mouse.move(bar.x + bar.width / 2, bar.y + bar.height / 2);
    await page.mouse.down();
    await page.mouse.move(bar.x + bar.width / 2, bar.y + bar.height / 2 - 150, { steps: 6 });
    await page.mouse.up();
    const dragged = { run: await heightOf(page, '.run-area'), drawing: await heightOf(page, '.canvas-column') };
    expect(dragged.run - before.run).toBeGreaterThan(140);
    expect(dragged.run - before.run).toBeLessThan(160);
    expect(before.drawing - dragged.drawing).toBeGreaterThan(140);
    const draggedShare = Number(await splitter.getAttribute('aria-valuenow'));
    expect(draggedShare).toBeGreaterThan(share);

    // the keyboard: ↓ gives the drawing back a step
    await splitter.focus();
    await page.keyboard.press('ArrowDown');
    await page.keyboard.press('ArrowDown');
    await expect(splitter).toHaveAttribute('aria-valuenow', String(draggedShare - 10));
    const keyed = await heightOf(page, '.run-area');
    expect(keyed).toBeLessThan(dragged.run - 40);

    // after a reload the split is where the user left it
    await page.reload();
    await expect(page.getByRole('separator', { name: 'Resize the drawing and the plots' })).toHaveAttribute('aria-valuenow', String(draggedShare - 10));
    expect(Math.abs(await heightOf(page, '.run-area') - keyed)).toBeLessThan(2);
    await page.evaluate(() => localStorage.removeItem('tlmhub.runAreaShare'));
});

test('ElectricVehicle: 12 variables on four axes in a maximised plot window with a compact legend; Esc restores', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'ElectricVehicle');
    for (const [component, port, variable] of VEHICLE) await plotVariable(page, component, port, variable);
    await runAndWait(page);
    const plot = windowOf(page);
    await expect(page.locator('.plot-window')).toHaveCount(1);
    await expect(plot).toHaveAttribute('data-axes', 'V,A,rad/s,Nm');
    const inList = (await plot.boundingBox())!;

    await plot.getByRole('button', { name: 'Maximise plot' }).click();
    const viewport = page.viewportSize()!;
    const maximised = (await plot.boundingBox())!;
    expect(maximised.width).toBe(viewport.width);
    expect(maximised.y + maximised.height).toBe(viewport.height);
    expect(maximised.height).toBeGreaterThan(viewport.height - 60);
    // one legend row per curve (and the time): swatch, name, value with its unit
    const rows = plot.locator('.u-legend .u-series');
    await expect(rows).toHaveCount(13);
    await expect(rows.nth(1).locator('.u-value')).toHaveText(/ V$/);
    await expect(rows.nth(4).locator('.u-value')).toHaveText(/ A$/);
    const rowHeights = await rows.evaluateAll((all) => all.map((r) => r.getBoundingClientRect().height));
    expect(Math.max(...rowHeights)).toBeLessThan(24);

    // the read-out at the cursor, and two cursors for the screenshot
    await plot.getByRole('button', { name: 'Two cursors' }).click();
    const over = (await plot.locator('.u-over').boundingBox())!;
    await page.mouse.move(over.x + over.width * 0.22, over.y + over.height * 0.5);
    await expect(rows.nth(1).locator('.u-value')).toHaveText(/^-?[\d.e+-]+ V$/);
    await page.screenshot({ path: `${docsScreenshots}plot-maximised-electric-vehicle.png` });

    await page.keyboard.press('Escape');
    await expect(plot).not.toHaveClass(/maximised/);
    const restored = (await plot.boundingBox())!;
    expect(restored.width).toBeCloseTo(inList.width, 0);
    expect(restored.height).toBeCloseTo(inList.height, 0);
    await expect(plot.getByRole('button', { name: 'Maximise plot' })).toHaveAttribute('aria-pressed', 'false');
});

test('40 curves: the legend scrolls and the graph keeps at least 200 px of height', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'ElectricVehicle');
    const names = await addPortVariables(page, {
        NodeElectric: [['Voltage', 'V'], ['Current', 'A'], ['WaveVariable', 'V']],
        NodeMechanicRotational: [['AngularVelocity', 'rad/s'], ['Torque', 'Nm']],
    }, 40);
    expect(names).toHaveLength(40);
    await runAndWait(page);
    const plot = windowOf(page);
    await expect(page.locator('.plot-window')).toHaveCount(1);
    await expect(plot.locator('.u-legend .u-series')).toHaveCount(41);
    // in the window as it opens, not maximised
    expect(await heightOf(page, '.plot-window .plot-canvas canvas')).toBeGreaterThanOrEqual(200);
    const legend = plot.locator('.plot-legend');
    const scroll = await legend.evaluate((el) => ({ scrollHeight: el.scrollHeight, clientHeight: el.clientHeight }));
    expect(scroll.scrollHeight).toBeGreaterThan(scroll.clientHeight);
    // the whole window is in sight in the run area as it opens
    await expect(plot).toBeInViewport({ ratio: 1 });
    await plot.screenshot({ path: 'e2e/screenshots/plot-40-curves.png' });
    // the last curve's row can be scrolled to
    const last = plot.locator('.u-legend .u-series').last();
    await last.scrollIntoViewIfNeeded();
    await expect(last).toBeInViewport();
    expect(await heightOf(page, '.plot-window .plot-canvas canvas')).toBeGreaterThanOrEqual(200);
});

test('a fifth unit asks: an axis more in the window, in sight of the drawing', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'ElectricVehicle');
    for (const [component, port, variable] of VEHICLE.slice(0, 11)) await plotVariable(page, component, port, variable);
    const plot = windowOf(page);
    await expect(plot.locator('.chip')).toHaveCount(11);
    // the state of charge is a signal (no unit): a fifth axis
    const soc = await plotVariable(page, 'ElectricBattery', 'soc', 'Value');
    const choice = page.getByTestId('axis-choice');
    await expect(choice).toBeInViewport();
    await expect(choice).toContainText('Plot 1 has 4 axes already (V, A, rad/s, Nm)');
    await expect(page.locator('.plot-window')).toHaveCount(1);
    await expect(plot.locator(`.chip[data-variable="${soc}"]`)).toHaveCount(0);

    await choice.getByRole('button', { name: 'Add an axis to Plot 1' }).click();
    await expect(choice).toBeHidden();
    await expect(plot.locator(`.chip[data-variable="${soc}"]`)).toHaveCount(1);
    await runAndWait(page);
    await expect(plot).toHaveAttribute('data-axes', 'V,A,rad/s,Nm,');
    await expect(page.locator('.plot-window')).toHaveCount(1);
});

/** Where the curve passes through time `t` (linear between the samples around it). */
function at(time: number[], values: number[], t: number): number {
    const i = time.findIndex((x) => x >= t);
    if (i <= 0) return values[Math.max(i, 0)];
    return values[i - 1] + (values[i] - values[i - 1]) * (t - time[i - 1]) / (time[i] - time[i - 1]);
}

test('two cursors: dragged and moved by keys, with Δt and each curve\'s Δvalue', async ({ page }) => {
    await login(page, 'bob');
    await openExample(page, 'ElectricVehicle');
    const voltage = await plotVariable(page, 'ElectricBattery', 'Pel1', 'Voltage');
    await plotVariable(page, 'ElectricBattery', 'Pel1', 'Current');
    await runAndWait(page);
    const plot = windowOf(page);
    const toggle = plot.getByRole('button', { name: 'Two cursors' });
    await toggle.click();
    await expect(toggle).toHaveAttribute('aria-pressed', 'true');
    const a = plot.getByRole('slider', { name: 'Cursor A' });
    const b = plot.getByRole('slider', { name: 'Cursor B' });
    await expect(a).toBeVisible();

    // B dragged to 80 % of the plot's width
    const over = (await plot.locator('.u-over').boundingBox())!;
    const bBox = (await b.boundingBox())!;
    await page.mouse.move(bBox.x + bBox.width / 2, over.y + over.height / 2);
    await page.mouse.down();
    await page.mouse.move(over.x + over.width * 0.8, over.y + over.height / 2, { steps: 5 });
    await page.mouse.up();
    // A a step to the right with the keyboard
    const aBefore = Number(await a.getAttribute('aria-valuenow'));
    await a.focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => Number(await a.getAttribute('aria-valuenow'))).toBeGreaterThan(aBefore);
    // the drag did not zoom
    expect(await plot.getAttribute('data-points')).not.toBe('0');

    const ta = Number(await a.getAttribute('aria-valuenow'));
    const tb = Number(await b.getAttribute('aria-valuenow'));
    expect(tb / 140).toBeCloseTo(0.8, 1);
    const readout = plot.getByTestId('delta-readout');
    const six = (v: number) => String(Number(v.toPrecision(6)));
    await expect(readout).toHaveText(`A ${six(ta)} s · B ${six(tb)} s · Δt ${six(tb - ta)} s`);

    const { time, values } = await page.evaluate((name) => {
        const app = (window as unknown as { __tlmhub: { runs: { current: { time: number[] } }; plots: { windows: { seriesData(n: string): number[] }[] } } }).__tlmhub;
        return { time: [...app.runs.current.time], values: [...app.plots.windows[0].seriesData(name)] };
    }, voltage);
    const delta = await plot.locator('.u-legend .u-series').nth(1).locator('.delta').textContent();
    const match = /^Δ (-?[\d.e+-]+) V$/.exec(delta ?? '');
    expect(match, `Δ cell "${delta}"`).not.toBeNull();
    expect(Number(match![1])).toBeCloseTo(at(time, values, tb) - at(time, values, ta), 3);
    await expect(plot.locator('.u-legend .u-series').nth(2).locator('.delta')).toHaveText(/^Δ -?[\d.e+-]+ A$/);

    await toggle.click();
    await expect(a).toHaveCount(0);
    await expect(readout).toBeHidden();
    await expect(plot.locator('.u-legend .delta')).toHaveCount(0);
});

test('a detached plot window keeps streaming in its own browser window, and comes back when closed', async ({ page, context }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    // a long run (10^7 steps), to see frames arrive in the detached window
    await setRunField(page, 'Stop time', '1000');
    await page.getByTestId('run').click();
    const plot = windowOf(page);
    await expect.poll(async () => Number(await plot.getAttribute('data-points')), { timeout: 30_000 }).toBeGreaterThan(10);

    const opened = context.waitForEvent('page');
    await plot.getByRole('button', { name: 'Detach plot' }).click();
    const popup = await opened;
    const detached = popup.locator('.plot-window');
    await expect(detached).toBeVisible();
    await expect(detached.locator('.plot-canvas canvas').first()).toBeVisible();
    await expect(page.locator('.plot-list .plot-window')).toHaveCount(0);
    await expect(page.locator('.plot-placeholder')).toContainText('Plot 1 is open in a window of its own');

    // frames keep coming while the run goes on
    await expect(detached).toHaveAttribute('data-state', 'running');
    const first = Number(await detached.getAttribute('data-points'));
    await expect.poll(async () => Number(await detached.getAttribute('data-points')), { timeout: 30_000 }).toBeGreaterThan(first);
    // and the window fills the popup
    const size = popup.viewportSize() ?? await popup.evaluate(() => ({ width: innerWidth, height: innerHeight }));
    expect((await detached.boundingBox())!.width).toBeGreaterThan(size.width - 4);
    // the canvas drew into the popup (not blank)
    const inked = await detached.locator('.plot-canvas canvas').first().evaluate((c: HTMLCanvasElement) => {
        const data = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
        let n = 0;
        for (let i = 3; i < data.length; i += 4) if (data[i] > 0) ++n;
        return n;
    });
    expect(inked).toBeGreaterThan(1000);
    await popup.screenshot({ path: 'e2e/screenshots/plot-detached.png' });

    await popup.close();
    await expect(page.locator('.plot-list .plot-window')).toHaveCount(1);
    await expect(page.locator('.plot-placeholder')).toHaveCount(0);
    await expect(plot.locator('.plot-canvas canvas').first()).toBeVisible();
    await expect(plot.getByRole('button', { name: 'Detach plot' })).toBeVisible();
    await page.getByTestId('cancel').click();
});

// Issue 38.5's goal, reported and not asserted (no wall-clock asserts): 16 curves of 100,000
// samples panned and zoomed, one x range per animation frame, as a drag or the wheel would.
test('frame times of a 16-curve plot of a 100,000-sample run while panning and zooming (reported)', async ({ page }) => {
    await login(page, 'bob');
    // few enough variables that 100,000 samples of all of them stay within the server's result limit
    await openExample(page, 'Electric Capacitances & Resistors');
    const names = await addPortVariables(page, { NodeElectric: [['Voltage', 'V'], ['Current', 'A']] }, 16);
    expect(names).toHaveLength(16);
    // 100,000 steps of 1 ms
    await setRunField(page, 'Stop time', '100');
    await setRunField(page, 'Log samples', '100000');
    await runAndWait(page);
    const plot = windowOf(page);
    await expect.poll(async () => Number(await plot.getAttribute('data-points')), { timeout: 30_000 }).toBe(100_000);
    const frames = await page.evaluate(async () => {
        type Chart = { data: number[][]; hooks: { draw?: (() => void)[] }; setScale(key: string, range: { min: number; max: number }): void };
        const app = (window as unknown as { __tlmhub: { plots: { windows: { surface: { plot: Chart } }[] } } }).__tlmhub;
        const u = app.plots.windows[0].surface.plot;
        const xs = u.data[0];
        const [first, last] = [xs[0], xs[xs.length - 1]];
        const span = last - first;
        let drawn = 0;
        (u.hooks.draw ??= []).push(() => { drawn = performance.now(); });
        const nextFrame = () => new Promise<number>((resolve) => requestAnimationFrame(resolve));
        const work: number[] = [];
        const intervals: number[] = [];
        let previous = await nextFrame();
        for (let k = 0; k < 240; ++k) {
            // zoom from all of it to a twentieth, then pan that twentieth across, then zoom out
            const phase = k % 120;
            const width = phase < 60 ? span * (1 - 0.95 * phase / 59) : span / 20;
            const min = phase < 60 ? first + (span - width) / 2 : first + (span - width) * (phase - 60) / 59;
            const start = performance.now();
            u.setScale('x', { min, max: min + width });
            await Promise.resolve();
            work.push(drawn - start);
            const now = await nextFrame();
            intervals.push(now - previous);
            previous = now;
        }
        return { work, intervals };
    });
    const stats = (values: number[]) => {
        const sorted = [...values].sort((a, b) => a - b);
        const q = (p: number) => sorted[Math.min(sorted.length - 1, Math.floor(p * sorted.length))].toFixed(1);
        return `median ${q(0.5)} ms, 95th percentile ${q(0.95)} ms, max ${sorted[sorted.length - 1].toFixed(1)} ms`;
    };
    // frames 0-59 (and 120-179) zoom in from the whole run; the others pan a twentieth of it
    const zooming = frames.work.filter((_, k) => k % 120 < 60);
    const panning = frames.work.filter((_, k) => k % 120 >= 60);
    console.log(`16 curves x 100,000 samples, ${frames.work.length} pan/zoom frames in Chromium:\n`
        + `  redraw per frame, zooming: ${stats(zooming)}\n  redraw per frame, panning: ${stats(panning)}\n`
        + `  all frames: ${stats(frames.work)}\n  frame interval: ${stats(frames.intervals)}`);
    expect(frames.work.every((t) => t > 0)).toBe(true);
});
