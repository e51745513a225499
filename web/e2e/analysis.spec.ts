// Issue 13.4: the spectrum (FFT) window of a plotted variable, and the Bode window (issue 38.7).
import { mkdirSync, copyFileSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect } from './fixtures';
import { login, openExample, plotVariable, runAndWait, setRunField } from './helpers';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

test('the FFT window of a 7.3 Hz sine source peaks at 7.3 Hz', async ({ page }) => {
    await login(page, 'bob');
    await page.locator('input[name="new-model-name"]').fill('Sine spectrum');
    await page.getByRole('button', { name: 'Create' }).click();
    await expect(page.getByTestId('model-name')).toHaveText('Sine spectrum');
    await page.getByLabel('Search components').fill('SignalSineWave');
    await page.locator('.palette-item[data-type="SignalSineWave"]').dblclick();
    const sine = page.locator('.canvas .component').first();
    await expect(sine).toBeVisible();
    const name = (await sine.getAttribute('data-name'))!;
    await sine.locator('.icon-frame').click();
    const frequency = page.getByLabel('f#Value value');
    await frequency.fill('7.3');
    await frequency.press('Enter');
    await expect(page.locator('.parameter-panel .field-error')).toHaveCount(0);
    await plotVariable(page, name, 'out', 'Value');
    await setRunField(page, 'Stop time', '10');
    await setRunField(page, 'Log samples', '2048');
    await runAndWait(page);

    await page.locator('.plot-window').first().getByRole('button', { name: 'FFT' }).click();
    const fft = page.locator('.analysis-window[data-analysis="fft"]');
    await expect(fft.locator('canvas').first()).toBeVisible();
    await expect(fft).toHaveAttribute('data-peak-hz', /\d/);
    // 2048 samples over 10 s, zero-padded to 2048: one bin is (2047 / 10 s) / 2048
    const bin = 2047 / 10 / 2048;
    expect(Math.abs(Number(await fft.getAttribute('data-peak-hz')) - 7.3)).toBeLessThanOrEqual(bin);
    await expect(fft.getByTestId('analysis-note')).toContainText(/peak at [\d.]+ Hz/);

    const [csv] = await Promise.all([page.waitForEvent('download'), fft.getByRole('button', { name: 'CSV' }).click()]);
    const lines = readFileSync(await csv.path(), 'utf8').trim().split('\n');
    expect(lines[0]).toMatch(/^frequency \[Hz\],/);
    expect(lines.length).toBeGreaterThan(1000);
});

test('the Bode window draws gain above phase of the servo position against its step source, wrapped or unwrapped', async ({ page }) => {
    // a run area tall enough to show the two charts whole
    await page.setViewportSize({ width: 1440, height: 1700 });
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    // only the output is plotted: the step that drives the servo is the input without being chosen
    const position = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    await runAndWait(page);
    await page.locator('.plot-window').first().getByRole('button', { name: 'Bode' }).click();
    const bode = page.locator('.analysis-window[data-analysis="bode"]');
    await expect(bode.getByLabel('Input')).toHaveValue('Step#out#Value');
    await expect(bode.getByLabel('Output')).toHaveValue(position);
    await bode.getByLabel('Window').selectOption('rectangular');
    // from just before the step at 1 s: the servo settling from its start is no answer to the step
    await bode.getByLabel('From time').fill('0.9');
    await bode.getByLabel('From time').press('Enter');
    await expect(bode.getByTestId('analysis-note')).toContainText('frequencies');

    // two charts, gain above phase, whose plot areas line up
    const gain = bode.locator('[data-plot="gain"]');
    const phase = bode.locator('[data-plot="phase"]');
    await expect(gain.locator('canvas')).toBeVisible();
    await expect(phase.locator('canvas')).toBeVisible();
    await bode.scrollIntoViewIfNeeded();
    const g = (await gain.locator('.u-over').boundingBox())!;
    const p = (await phase.locator('.u-over').boundingBox())!;
    expect(g.y + g.height).toBeLessThan(p.y);
    expect(Math.abs(g.x - p.x)).toBeLessThan(1);
    expect(Math.abs(g.width - p.width)).toBeLessThan(1);
    // One frequency axis: a zoom (drag) on the gain zooms the phase to the same range. Here to
    // about 0.4-30 Hz (of 0.33-340 Hz), the band where the servo answers the step; above it the
    // output is noise, whose unwrapped phase wanders by thousands of degrees.
    const range = async (chart: typeof gain) => (await chart.getAttribute('data-x-range'))!.split(' ').map(Number);
    const full = await range(gain);
    expect(await range(phase)).toEqual(full);
    await page.mouse.move(g.x + g.width * 0.02, g.y + g.height / 2);
    await page.mouse.down();
    await page.mouse.move(g.x + g.width * 0.65, g.y + g.height / 2, { steps: 5 });
    await page.mouse.up();
    await expect.poll(async () => (await range(gain))[0]).toBeGreaterThan(full[0]);
    const zoomed = await range(gain);
    expect(zoomed[1]).toBeLessThan(full[1]);
    expect(await range(phase)).toEqual(zoomed);
    mkdirSync(screenshots, { recursive: true });
    mkdirSync(docsScreenshots, { recursive: true });
    await bode.screenshot({ path: `${screenshots}bode.png` });
    copyFileSync(`${screenshots}bode.png`, `${docsScreenshots}bode-plot.png`);

    // the PNG holds both charts, one under the other
    const [png] = await Promise.all([page.waitForEvent('download'), bode.getByRole('button', { name: 'PNG' }).click()]);
    const image = readFileSync(await png.path());
    expect(image.subarray(1, 4).toString()).toBe('PNG');
    const canvasHeight = (chart: typeof gain) => chart.locator('canvas').evaluate((c) => (c as HTMLCanvasElement).height);
    expect(image.readUInt32BE(20)).toBeGreaterThan(await canvasHeight(gain) + await canvasHeight(phase));   // IHDR height

    // the diagram as exported, one row per frequency: [frequency, gain, phase]
    const rows = async () => {
        const [csv] = await Promise.all([page.waitForEvent('download'), bode.getByRole('button', { name: 'CSV' }).click()]);
        const lines = readFileSync(await csv.path(), 'utf8').trim().split('\n');
        expect(lines[0]).toBe('frequency [Hz],gain [dB],phase [°]');
        return lines.slice(1).map((l) => l.split(',').map(Number));
    };
    // Unwrapped (the default), the lag grows past -180° (near 8 Hz) while the position still
    // follows the step (gain within 3 dB of 0).
    const unwrapped = await rows();
    const past = unwrapped.find(([, , deg]) => deg < -180)!;
    expect(past[0]).toBeLessThan(10);
    expect(Math.abs(past[1])).toBeLessThan(3);
    // Wrapped, the same phases modulo 360°, each in (-180°, 180°].
    await bode.getByLabel('Phase').selectOption('wrapped');
    await expect.poll(async () => (await rows()).find(([f]) => f === past[0])![2]).toBeGreaterThan(-180);
    const wrapped = await rows();
    expect(wrapped.map(([f]) => f)).toEqual(unwrapped.map(([f]) => f));
    wrapped.forEach(([, , deg], i) => {
        expect(deg).toBeGreaterThan(-180);
        expect(deg).toBeLessThanOrEqual(180);
        const turns = (unwrapped[i][2] - deg) / 360;
        expect(Math.abs(turns - Math.round(turns))).toBeLessThan(1e-6);
    });
});

test('the XY window plots the cylinder pressure over the mass position, point for point', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const position = await plotVariable(page, 'Mass', 'P2', 'Position');
    await plotVariable(page, 'Cylinder_C', 'P1', 'Pressure');
    await runAndWait(page);
    // The plot draws the finished run on its next update, a moment after the status says done.
    const timePlot = page.locator('.plot-window').first();
    await expect(timePlot).toHaveAttribute('data-state', 'done');
    const points = Number(await timePlot.getAttribute('data-points'));
    await page.locator('.plot-window').first().getByRole('button', { name: 'XY' }).click();
    const xy = page.locator('.analysis-window[data-analysis="xy"]');
    await expect(xy.getByLabel('X variable')).toHaveValue(position);
    await expect(xy.locator('canvas').first()).toBeVisible();
    await expect(xy).toHaveAttribute('data-points', String(points));
    // a time range takes only its samples
    await xy.getByLabel('From time').fill('1.5');
    await xy.getByLabel('From time').press('Enter');
    await expect.poll(async () => Number(await xy.getAttribute('data-points'))).toBeLessThan(points);
    await xy.screenshot({ path: `${screenshots}xy.png` });
});
