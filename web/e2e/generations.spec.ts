// Issue 38 item 3: a plot window steps through the model's runs (Hopsan's plot generations)
// in the order they were run, with ◀ ▶ and Ctrl+← Ctrl+→; each curve names its run; the newest
// run is shown by default, with the run before it to compare; a run chosen in the Runs panel
// takes its place in time; the difference of two runs on demand; analyses of the shown run.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Locator } from '@playwright/test';
import { test, expect, type Page } from './fixtures';
import { login, openExample, plotted, plotVariable, runAndWait, setServoGain } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

/** The difference curve of a variable in the first plot window, as drawn. */
async function plottedDifference(page: Page, name: string): Promise<{ time: number[]; data: number[] } | null> {
    return page.evaluate((n) => {
        type Source = { time: number[]; data: number[] };
        const app = (window as unknown as { __tlmhub: { plots: { windows: { differenceData(n: string): Source | null }[] } } }).__tlmhub;
        const d = app.plots.windows[0].differenceData(n);
        return d && { time: [...d.time], data: [...d.data] };
    }, name);
}

/** The x values of an XY window, from its CSV export. */
/** Runs Position Servo with three gains; each run's job id and its plotted position curve. */
async function runThreeGains(page: Page, plot: Locator, position: string): Promise<{ jobs: number[]; curves: number[][] }> {
    const jobs: number[] = [];
    const curves: number[][] = [];
    for (const gain of ['0.001', '0.005', '0.02']) {
        await setServoGain(page, gain);
        const job = await runAndWait(page);
        await expect(plot).toHaveAttribute('data-job', String(job));
        await expect.poll(async () => (await plotted(page, position)).length).toBeGreaterThan(100);
        jobs.push(job);
        curves.push(await plotted(page, position));
    }
    return { jobs, curves };
}

async function xyColumn(page: Page, xy: Locator): Promise<number[]> {
    const [csv] = await Promise.all([page.waitForEvent('download'), xy.getByRole('button', { name: 'CSV' }).click()]);
    const [, ...rows] = readFileSync(await csv.path(), 'utf8').trim().split('\n');
    return rows.map((row) => Number(row.split(',')[0]));
}

test('three runs overlaid and stepped through', async ({ page }) => {
    await login(page, 'bob');
    await openExample(page, 'Position Servo');
    const position = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    const plot = page.locator('.plot-window').first();
    const generation = plot.getByTestId('generation');
    const legend = plot.locator('.u-legend .u-series:not(:first-child) .u-label');

    // three runs, each with another gain: three different curves
    const { jobs, curves } = await runThreeGains(page, plot, position);
    expect(curves[1]).not.toEqual(curves[0]);
    expect(curves[2]).not.toEqual(curves[1]);
    const [first, second, third] = jobs;

    // the newest run, named in the legend, and the one before it to compare
    await expect(generation).toHaveText(new RegExp(`^run ${third} \\(\\d+ of \\d+\\)$`));
    await plot.locator('input[name="compare"]').check();
    await expect(legend).toHaveText([`Position_Sensor.out Value (run ${third})`, `Position_Sensor.out Value (run ${second})`]);
    await expect.poll(() => plotted(page, position, true)).toEqual(curves[1]);
    await expect(plot.getByRole('button', { name: 'Later run' })).toBeDisabled();

    // back with the keyboard: the window has the focus once clicked
    await plot.locator('.plot-body').click();
    await page.keyboard.press('Control+ArrowLeft');
    await expect(generation).toHaveText(new RegExp(`^run ${second} `));
    await expect(plot).toHaveAttribute('data-job', String(second));
    await expect(legend).toHaveText([`Position_Sensor.out Value (run ${second})`, `Position_Sensor.out Value (run ${first})`]);
    await expect.poll(() => plotted(page, position)).toEqual(curves[1]);
    await expect.poll(() => plotted(page, position, true)).toEqual(curves[0]);

    await page.keyboard.press('Control+ArrowLeft');
    await expect(generation).toHaveText(new RegExp(`^run ${first} `));
    await expect.poll(() => plotted(page, position)).toEqual(curves[0]);

    // forward with the buttons, back to the newest
    await plot.getByRole('button', { name: 'Later run' }).click();
    await expect(generation).toHaveText(new RegExp(`^run ${second} `));
    await page.keyboard.press('Control+ArrowRight');
    await expect(generation).toHaveText(new RegExp(`^run ${third} `));
    await expect.poll(() => plotted(page, position)).toEqual(curves[2]);
    await expect(plot.getByRole('button', { name: 'Later run' })).toBeDisabled();

    // a new run is shown as it comes, even from a window stepped back
    await plot.getByRole('button', { name: 'Earlier run' }).click();
    await expect(generation).toHaveText(new RegExp(`^run ${second} `));
    const fourth = await runAndWait(page);
    await expect(generation).toHaveText(new RegExp(`^run ${fourth} `));
});

test('a run chosen in the panel takes its place in time; a difference of two runs and an XY window follow the shown run', async ({ page }) => {
    await login(page, 'bob');
    await openExample(page, 'Position Servo');
    const position = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    // an own copy, opened afresh: its runs are this test's only
    await page.getByTestId('save').click();
    await expect(page.getByTestId('save')).toHaveText('Save');
    await page.reload();
    const panel = page.getByRole('complementary', { name: 'Run history' });
    const plot = page.locator('.plot-window').first();
    const generation = plot.getByTestId('generation');
    const legend = plot.locator('.u-legend .u-series:not(:first-child) .u-label');
    await expect(plot.locator('.chip')).toHaveCount(1);

    const { jobs, curves } = await runThreeGains(page, plot, position);
    const [first, second, third] = jobs;
    await expect(generation).toHaveText(`run ${third} (3 of 3)`);

    // the oldest run, chosen in the panel, is the first of the three: ▶ goes to the second
    await panel.locator(`.history-row[data-job="${first}"] .history-show`).click();
    await expect(plot).toHaveAttribute('data-job', String(first));
    await expect(generation).toHaveText(`run ${first} (1 of 3)`);
    await expect.poll(() => plotted(page, position)).toEqual(curves[0]);
    await expect(plot.getByRole('button', { name: 'Earlier run' })).toBeDisabled();

    // an XY window opened now plots the chosen run, and follows the window's stepping
    await plot.getByRole('button', { name: 'XY' }).click();
    const xy = page.locator('.analysis-window[data-analysis="xy"]');
    await expect(xy).toHaveAttribute('data-points', String(curves[0].length));
    await expect.poll(() => xyColumn(page, xy)).toEqual(curves[0]);
    await plot.getByRole('button', { name: 'Later run' }).click();
    await expect(generation).toHaveText(`run ${second} (2 of 3)`);
    await expect.poll(() => xyColumn(page, xy)).toEqual(curves[1]);
    await xy.getByRole('button', { name: 'Close XY plot' }).click();

    // the difference of each variable: the shown run minus the one before it in time
    await plot.getByRole('button', { name: 'Difference of two runs' }).click();
    await expect(legend).toHaveText([`Position_Sensor.out Value (run ${second})`, `Position_Sensor.out Value: run ${second} − run ${first}`]);
    const difference = (await plottedDifference(page, position))!;
    expect(difference.data).toHaveLength(curves[1].length);   // one step size: B needs no interpolation
    const i = Math.floor(difference.time.length / 2);
    expect(difference.time[i]).toBeGreaterThan(0);
    expect(difference.data[i]).toBe(curves[1][i] - curves[0][i]);
    expect(Math.abs(difference.data[i])).toBeGreaterThan(0);
    // B picked: the newest run
    await plot.getByLabel('Difference run B').selectOption(String(third));
    await expect(legend).toHaveText([`Position_Sensor.out Value (run ${second})`, `Position_Sensor.out Value: run ${second} − run ${third}`]);
    await expect.poll(async () => (await plottedDifference(page, position))!.data[i]).toBe(curves[1][i] - curves[2][i]);
    await plot.getByRole('button', { name: 'Difference of two runs' }).click();
    await expect(legend).toHaveCount(1);

    // all three runs overlaid, the newest solid
    await plot.locator('.plot-body').click();
    await page.keyboard.press('Control+ArrowRight');
    await expect(generation).toHaveText(`run ${third} (3 of 3)`);
    await plot.locator('input[name="allRuns"]').check();
    await expect(legend).toHaveText([third, second, first].map((job) => `Position_Sensor.out Value (run ${job})`));
    await page.mouse.move(0, 0);
    await expect(page.locator('.toast')).toHaveCount(0, { timeout: 10_000 });
    await plot.screenshot({ path: `${docsScreenshots}position-servo-generations.png` });
});
