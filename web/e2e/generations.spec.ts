// Issue 38 item 3: a plot window steps through the model's runs (Hopsan's plot generations)
// with ◀ ▶ and Ctrl+← Ctrl+→; each curve names its run; the newest run is shown by default,
// with the run before it to compare.
import { test, expect } from './fixtures';
import { login, openExample, plotted, plotVariable, runAndWait, setServoGain } from './helpers';

test('three runs overlaid and stepped through', async ({ page }) => {
    await login(page, 'bob');
    await openExample(page, 'Position Servo');
    const position = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    const plot = page.locator('.plot-window').first();
    const generation = plot.getByTestId('generation');
    const legend = plot.locator('.u-legend .u-series:not(:first-child) .u-label');

    // three runs, each with another gain: three different curves
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
