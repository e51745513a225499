// Issue 38.4: a display unit per quantity, chosen on a plot's axis and stored for the user on
// the server (GET/PUT /api/v1/preferences); the axis, the cursor read-out, the legend and the
// CSV in display units agree, and the default CSV stays in base units.
import { readFileSync } from 'node:fs';
import type { Locator } from '@playwright/test';
import { test, expect, type Page } from './fixtures';
import { baseUrl, login, openExample, plotVariable, runAndWait, tokenOf } from './helpers';

type Csv = string[][];

async function downloadCsv(page: Page, plot: Locator, button: string): Promise<Csv> {
    const [download] = await Promise.all([page.waitForEvent('download'), plot.getByRole('button', { name: button, exact: true }).click()]);
    return readFileSync((await download.path())!, 'utf8').trim().split('\n').map((line) => line.split(','));
}

test('units switched to bar and L/min with axis, readout and CSV agreeing', async ({ page, request }) => {
    await login(page, 'bob');
    const preferences = `${baseUrl()}/api/v1/preferences`;
    const headers = { Authorization: `Bearer ${await tokenOf(page)}` };
    const stored = async () => (await request.get(preferences, { headers })).json();
    // start with no choice (the user may have chosen in an earlier run of the suite)
    const reset = await request.put(preferences, { headers, data: { units: {} } });
    expect(reset.status(), 'PUT /api/v1/preferences: the server must have the preferences route').toBe(200);

    await openExample(page, 'Position Servo');
    const pressure = await plotVariable(page, 'Cylinder_C', 'P1', 'Pressure');
    const flow = await plotVariable(page, 'Cylinder_C', 'P1', 'Flow');
    await runAndWait(page);
    const plot = page.locator('.plot-window').first();
    await expect(plot).toHaveAttribute('data-axes', /^[kM]?Pa,m\^3\/s$/);

    await plot.getByRole('combobox', { name: 'Pressure unit' }).selectOption('bar');
    await plot.getByRole('combobox', { name: 'Flow unit' }).selectOption('l/min');
    // the axes, the legend and the server say the chosen units
    await expect(plot).toHaveAttribute('data-axes', 'bar,l/min');
    const labels = plot.locator('.u-legend .u-series:not(:first-child) .u-label');
    await expect(labels).toHaveText([/Pressure \(run \d+\) \[bar\]$/, /Flow \(run \d+\) \[l\/min\]$/]);
    await expect.poll(stored).toEqual({ units: { Pressure: 'bar', Flow: 'l/min' } });

    // the default CSV is in base units as before; the other one converts and names its units
    const logged = await downloadCsv(page, plot, 'CSV');
    const shown = await downloadCsv(page, plot, 'CSV in display units');
    expect(logged[0]).toEqual(['time', pressure, flow]);
    expect(shown[0]).toEqual(['time [s]', `${pressure} [bar]`, `${flow} [l/min]`]);
    expect(shown).toHaveLength(logged.length);
    for (let i = 1; i < logged.length; ++i) {
        expect(shown[i][0]).toBe(logged[i][0]);
        expect(Number(shown[i][1])).toBeCloseTo(Number(logged[i][1]) / 1e5, 9);
        expect(Number(shown[i][2])).toBeCloseTo(Number(logged[i][2]) * 60_000, 9);
    }

    // the read-out under the cursor is a row of that CSV, in its units
    const box = (await plot.locator('.u-over').boundingBox())!;
    await page.mouse.move(box.x + box.width * 0.6, box.y + box.height / 2);
    const values = plot.locator('.u-legend .u-series .u-value');
    await expect(values.nth(1)).toHaveText(/^-?[\d.e+-]+ bar$/);
    const [time, pressureValue, flowValue] = (await values.allTextContents()).map((text) => text.split(' ')[0]);
    const sixDigits = (v: string) => String(Number(Number(v).toPrecision(6)));
    const rows = shown.slice(1).filter((row) => Math.abs(Number(row[0]) - Number(time)) <= 0.0005);
    expect(rows.length, `CSV rows at the cursor's time ${time}`).toBeGreaterThan(0);
    expect(rows.some((row) => sixDigits(row[1]) === pressureValue && sixDigits(row[2]) === flowValue),
        `read-out ${pressureValue} bar, ${flowValue} l/min is a CSV row near t = ${time}`).toBe(true);
    await expect(values.nth(2)).toHaveText(/ l\/min$/);

    // remembered: after a reload the plot comes back in bar and l/min
    await page.reload();
    const again = page.locator('.plot-window').first();
    await expect(again).toHaveAttribute('data-axes', 'bar,l/min');
    await expect(again.getByRole('combobox', { name: 'Pressure unit' })).toHaveValue('bar');

    // back to SI prefixes, and no choice left for the other tests of this user
    await again.getByRole('combobox', { name: 'Pressure unit' }).selectOption('');
    await expect(again).toHaveAttribute('data-axes', /^[kM]?Pa,l\/min$/);
    await expect.poll(stored).toEqual({ units: { Flow: 'l/min' } });
    expect((await request.put(preferences, { headers, data: { units: {} } })).status()).toBe(200);
});
