// Issue 38 items 2 and 3: the run history beside the plots. After a reload it lists the
// model's runs; hovering one names the parameters it used otherwise than the latest run; a
// run's name and pin are kept; a clicked run is shown in the plot window, in its place in time.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect, type Page } from './fixtures';
import { login, openExample, plotVariable, runAndWait, setServoGain } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

async function save(page: Page): Promise<void> {
    await page.getByTestId('save').click();
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
}

test('the run history lists the runs, names their differences, keeps names and pins, and plots a chosen run', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const panel = page.getByRole('complementary', { name: 'Run history' });
    const rows = panel.locator('.history-row');
    await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    await runAndWait(page);
    await expect(rows).not.toHaveCount(0);   // her runs of the example
    // an own copy: a history of this test's runs only, from the moment it is saved
    await page.getByTestId('save').click();
    await expect(page.getByTestId('save')).toHaveText('Save');
    await expect(rows).toHaveCount(0);
    await page.locator('.canvas .component[data-name="GainP"] .icon-frame').click();
    const original = await page.getByLabel('k#Value value').inputValue();

    const first = await runAndWait(page);
    await setServoGain(page, '0.02');
    await save(page);
    const second = await runAndWait(page);
    await expect(rows).toHaveCount(2);

    await page.reload();
    await expect(rows).toHaveCount(2);
    const older = panel.locator(`.history-row[data-job="${first}"]`);
    const newer = panel.locator(`.history-row[data-job="${second}"]`);
    await expect(rows.locator('.history-label')).toHaveText([`run ${second}`, `run ${first}`]);
    await expect(newer).toHaveAttribute('aria-current', 'true');   // the run the plot shows
    await older.hover();
    const difference = `GainP.k: ${original} (latest 0.02)`;
    await expect(older).toHaveAttribute('title', new RegExp(difference.replace(/[.()]/g, '\\$&')));
    await expect(older.locator('.history-show')).toHaveAccessibleDescription(new RegExp(difference.replace(/[.()]/g, '\\$&')));
    await expect(newer).toHaveAttribute('title', /The latest run/);

    // a name the server refuses is shown with its reason; Enter saves one it takes
    await older.hover();
    await older.getByRole('button', { name: `Rename run ${first}` }).click();
    const name = older.getByLabel(`Name of run ${first}`);
    await name.fill('bad\tname');
    await name.press('Enter');
    await expect(older.locator('.history-edit .field-error')).not.toBeEmpty();
    await name.fill('baseline');
    await name.press('Enter');
    await expect(older.locator('.history-label')).toHaveText('baseline');
    const pin = older.getByRole('button', { name: 'Pin baseline' });
    await pin.click();
    await expect(pin).toHaveAttribute('aria-pressed', 'true');

    await page.reload();
    await expect(older.locator('.history-label')).toHaveText('baseline');
    await expect(older.getByRole('button', { name: 'Pin baseline' })).toHaveAttribute('aria-pressed', 'true');
    await expect(newer.getByRole('button', { name: `Pin run ${second}` })).toHaveAttribute('aria-pressed', 'false');

    // the older run, clicked, is the one the plot window shows
    const plot = page.locator('.plot-window').first();
    await expect(plot).toHaveAttribute('data-job', String(second));
    await older.locator('.history-show').click();
    await expect(plot).toHaveAttribute('data-job', String(first));
    await expect(plot.getByTestId('generation')).toHaveText(/^baseline \(/);
    await expect(older).toHaveAttribute('aria-current', 'true');
    await expect.poll(() => plot.getAttribute('data-points').then(Number)).toBeGreaterThan(10);

    // a third run comes first and is shown; the chosen one is shown again when clicked
    await setServoGain(page, '0.005');
    await save(page);
    const third = await runAndWait(page);
    await expect(rows).toHaveCount(3);
    await expect(plot).toHaveAttribute('data-job', String(third));
    await older.locator('.history-show').click();
    await expect(plot).toHaveAttribute('data-job', String(first));
    // in its place in time, the oldest of the three, whenever it was chosen
    await expect(plot.getByTestId('generation')).toHaveText('baseline (1 of 3)');
    // the middle one, compared with the run before it in time
    await newer.locator('.history-show').click();
    await expect(plot.getByTestId('generation')).toHaveText(`run ${second} (2 of 3)`);
    await plot.locator('input[name="compare"]').check();
    await expect(plot.locator('.u-legend .u-series:not(:first-child) .u-label')).toHaveText([new RegExp(`\\(run ${second}\\)$`), /\(baseline\)$/]);

    await page.mouse.move(0, 0);
    await expect(page.locator('.toast')).toHaveCount(0, { timeout: 10_000 });
    mkdirSync(docsScreenshots, { recursive: true });
    const area = (await page.locator('.run-area').boundingBox())!;
    const right = (await plot.boundingBox())!;
    await page.screenshot({ path: `${docsScreenshots}run-history-panel.png`, clip: { x: area.x, y: area.y, width: right.x + right.width + 10 - area.x, height: area.height } });
});
