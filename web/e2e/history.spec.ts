// Issue 38.2: after a reload the editor shows the model's last run again (from the server's
// run history) and reopens the plot windows the user had, with that run's curves.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect } from './fixtures';
import { login, openExample, plotVariable, plotted, runAndWait } from './helpers';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));

test('after a reload the run status names the last run and its plot window is back with the curve', async ({ page }) => {
    await login(page, 'alice');
    const modelId = await openExample(page, 'Position Servo');
    // (other specs may have run the example as alice already: its last run may show from the start)
    const position = await plotVariable(page, 'Mass', 'P2', 'Position');
    const job = await runAndWait(page);
    const curve = await plotted(page, position);
    expect(curve.length).toBeGreaterThan(10);

    await page.reload();
    const status = page.getByTestId('run-status');
    await expect(page.getByTestId('model-name')).toHaveText('Position Servo');
    expect(page.url()).toContain(`#/model/${modelId}`);
    await expect(status).toHaveAttribute('data-job', String(job));
    await expect(status).toHaveAttribute('data-state', 'done');
    await expect(status).toHaveText(`Job ${job}: done`);

    const plot = page.locator('.plot-window').first();
    await expect(page.locator('.plot-window')).toHaveCount(1);
    await expect(plot.locator('.chip')).toHaveText([/^Mass\.P2 Position/]);
    await expect(plot).toHaveAttribute('data-job', String(job));
    await expect(plot.locator('canvas').first()).toBeVisible();
    // the stored result of the run, drawn as it was before the reload
    await expect.poll(() => plotted(page, position)).toEqual(curve);
    expect(Number(await plot.getAttribute('data-points'))).toBe(curve.length);

    mkdirSync(screenshots, { recursive: true });
    await page.locator('.run-area').screenshot({ path: `${screenshots}history-restored.png` });
});
