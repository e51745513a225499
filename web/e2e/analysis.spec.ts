// Issue 13.4: the spectrum (FFT) window of a plotted variable, and the Bode window.
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

test('the Bode window shows gain and phase of the servo position against its step input', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    await plotVariable(page, 'Step', 'out', 'Value');
    await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    await runAndWait(page);
    await page.locator('.plot-window').first().getByRole('button', { name: 'Bode' }).click();
    const bode = page.locator('.analysis-window[data-analysis="bode"]');
    await bode.getByLabel('Window').selectOption('rectangular');
    await expect(bode.getByTestId('analysis-note')).toContainText('frequencies');
    await expect(bode.locator('canvas').first()).toBeVisible();
    await bode.scrollIntoViewIfNeeded();
    mkdirSync(screenshots, { recursive: true });
    mkdirSync(docsScreenshots, { recursive: true });
    await bode.screenshot({ path: `${screenshots}bode.png` });
    copyFileSync(`${screenshots}bode.png`, `${docsScreenshots}bode-plot.png`);
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
