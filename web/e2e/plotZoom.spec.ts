// Issue 38 items 2 and 5: a plot window zooms with the mouse wheel about the pointer (with Shift
// the y axes) and pans by a drag with the middle button or with Ctrl and the left one; a double
// click shows the whole run; the zoom comes back after a reload; the time axis says its unit.
import { test, expect, type Page } from './fixtures';
import { login, openExample, plotVariable, runAndWait } from './helpers';

interface Shown { x: [number, number]; y: [number, number]; run: [number, number] }

/** The time and first y range the first plot window shows, and the run's first and last time. */
function shown(page: Page): Promise<Shown> {
    return page.evaluate(() => {
        type Chart = { data: number[][]; scales: Record<string, { min: number; max: number }> };
        const app = (window as unknown as { __tlmhub: { plots: { windows: { surface: { plot: Chart | null } }[] } } }).__tlmhub;
        const u = app.plots.windows[0].surface.plot!;
        const xs = u.data[0];
        return { x: [u.scales.x.min, u.scales.x.max], y: [u.scales.y0.min, u.scales.y0.max], run: [xs[0], xs[xs.length - 1]] };
    });
}

const width = ([min, max]: [number, number]) => max - min;

async function plotServoPosition(page: Page): Promise<number> {
    await login(page, 'alice');
    const model = await openExample(page, 'Position Servo');
    await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    await runAndWait(page);
    await expect.poll(async () => Number(await page.locator('.plot-window').first().getAttribute('data-points'))).toBeGreaterThan(10);
    return model;
}

test('the wheel zooms time about the pointer (with Shift the y axis), a middle or Ctrl drag pans, a double click shows the whole run; the time axis says its unit', async ({ page }) => {
    await plotServoPosition(page);
    const plot = page.locator('.plot-window').first();
    await expect(plot).toHaveAttribute('data-time-axis', 'Time [s]');
    const whole = await shown(page);
    expect(whole.x).toEqual(whole.run);
    const over = (await plot.locator('.u-over').boundingBox())!;
    const pointer = { x: over.x + over.width * 0.25, y: over.y + over.height * 0.5 };
    // the legend's time row says its unit as the curves' rows do
    await page.mouse.move(pointer.x, pointer.y);
    await expect(plot.locator('.u-legend .u-series').first().locator('.u-label')).toHaveText('Time');
    await expect(plot.locator('.u-legend .u-series').first().locator('.u-value')).toHaveText(/^[\d.e+-]+ s$/);
    const anchor = whole.x[0] + 0.25 * width(whole.x);

    // wheel away from the user: a narrower time range, the time under the pointer in its place
    await page.mouse.wheel(0, -300);
    await expect.poll(async () => width((await shown(page)).x)).toBeLessThan(width(whole.x) * 0.8);
    const zoomed = await shown(page);
    expect((anchor - zoomed.x[0]) / width(zoomed.x)).toBeCloseTo(0.25, 2);
    expect(zoomed.x[0]).toBeGreaterThan(whole.x[0]);
    expect(zoomed.x[1]).toBeLessThan(whole.x[1]);

    // a middle-button drag 100 px to the right shows earlier times, by 100 px worth
    await page.mouse.down({ button: 'middle' });
    await page.mouse.move(pointer.x + 100, pointer.y, { steps: 5 });
    await page.mouse.up({ button: 'middle' });
    const panned = await shown(page);
    const shift = 100 * width(zoomed.x) / over.width;
    expect(panned.x[0]).toBeCloseTo(zoomed.x[0] - shift, 3);
    expect(width(panned.x)).toBeCloseTo(width(zoomed.x), 6);

    // Ctrl and the left button pan too (to later times), and do not zoom to the dragged span
    await page.keyboard.down('Control');
    await page.mouse.down();
    await page.mouse.move(pointer.x - 100, pointer.y, { steps: 5 });
    await page.mouse.up();
    await page.keyboard.up('Control');
    const back = await shown(page);
    expect(back.x[0]).toBeCloseTo(panned.x[0] + 200 * width(zoomed.x) / over.width, 3);
    expect(width(back.x)).toBeCloseTo(width(zoomed.x), 6);

    // Shift and the wheel zoom the y axis, the time range stays
    await page.keyboard.down('Shift');
    await page.mouse.wheel(0, -300);
    await page.keyboard.up('Shift');
    await expect.poll(async () => width((await shown(page)).y)).toBeLessThan(width(back.y) * 0.8);
    expect((await shown(page)).x).toEqual(back.x);

    // a double click: the whole run, the y axis fitting the curve again
    await page.mouse.dblclick(pointer.x, pointer.y);
    await expect.poll(async () => (await shown(page)).x).toEqual(whole.run);
    expect((await shown(page)).y).toEqual(whole.y);
});

test('a zoomed plot window comes back with the same time range after a reload', async ({ page }) => {
    const model = await plotServoPosition(page);
    const plot = page.locator('.plot-window').first();
    const over = (await plot.locator('.u-over').boundingBox())!;
    await page.mouse.move(over.x + over.width * 0.6, over.y + over.height * 0.5);
    await page.mouse.wheel(0, -400);
    await expect.poll(async () => width((await shown(page)).x)).toBeLessThan(width((await shown(page)).run) * 0.8);
    const zoomed = await shown(page);
    // remembered once the wheel rests, not on every frame
    const saved = () => page.evaluate((key) => JSON.parse(localStorage.getItem(key) ?? '[]'), `tlmhub.plots.${model}`);
    await expect.poll(async () => (await saved())[0]?.zoom?.x).toEqual(zoomed.x);

    await page.reload();
    const again = page.locator('.plot-window').first();
    await expect(again.locator('.chip')).toHaveCount(1);
    await expect.poll(async () => Number(await again.getAttribute('data-points'))).toBeGreaterThan(10);
    await expect.poll(async () => (await shown(page)).x).toEqual(zoomed.x);
});
