// Issue 40.4: studies in the browser. A 2-D sweep of Position Servo defined in the study panel
// shows its heat map (and is still there after a reload); an optimisation's best point is
// applied to the model as one step and undone; a sensitivity study draws its bands.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect, type Page } from './fixtures';
import { api, login, openExample, runAndWait } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

interface Best { run: number; parameters: Record<string, number>; objective: number }
interface Study { id: number; kind: string; state: string; model_id: number; summary: { best?: Best } }

async function openStudyPanel(page: Page) {
    await page.getByTestId('study-button').click();
    const dialog = page.getByTestId('study-dialog');
    await expect(dialog).toBeVisible();
    return dialog;
}

/** The value text of a top-level component parameter in the editor's model (what the server replied). */
async function modelParameter(page: Page, component: string, parameter: string): Promise<string | undefined> {
    return page.evaluate(([c, p]) => {
        const app = (window as unknown as { __tlmhub: { store: { model: { system: { components: { name: string; parameters: { name: string; value: string }[] }[] } } } } }).__tlmhub;
        return app.store.model.system.components.find((x) => x.name === c)?.parameters.find((x) => x.name === p)?.value;
    }, [component, parameter] as const);
}

async function addParameter(page: Page, name: string, fields: Record<string, string>) {
    await page.getByTestId('study-parameter-picker').selectOption(name);
    const row = page.locator(`[data-parameter="${name}"]`);
    await expect(row).toBeVisible();
    for (const [field, value] of Object.entries(fields)) await row.locator(`input[name="${field}"]`).fill(value);
}

async function addOutput(page: Page, variable: string) {
    await page.getByTestId('study-output-input').fill(variable);
    await page.getByTestId('study-output-add').click();
    await expect(page.locator(`[data-output="${variable}"]`)).toBeVisible();
}

test('a 2-D sweep of Position Servo defined in the study panel shows its heat map, also after a reload', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const dialog = await openStudyPanel(page);
    await expect(page.getByTestId('study-kind-sweep')).toBeChecked();
    await addParameter(page, 'GainP.k', { from: '0.005', to: '0.04', steps: '8' });
    await addParameter(page, 'GainI.k', { from: '0', to: '0.002', steps: '6' });
    await addOutput(page, 'Position_Sensor#out#Value');
    await dialog.getByLabel('Log samples').fill('200');
    await dialog.getByTestId('study-name').fill('gain map');
    mkdirSync(docsScreenshots, { recursive: true });
    await dialog.screenshot({ path: `${docsScreenshots}study-form.png` });

    await page.getByTestId('study-start').click();
    const progress = page.getByTestId('study-progress');
    await expect(progress).toBeVisible();
    const id = await page.getByTestId('study-list').locator('li.chosen').getAttribute('data-study');
    // the progress survives a reload: the panel lists the study and follows it again
    await page.reload();
    await expect(page.getByTestId('model-name')).toHaveText('Position Servo');
    await openStudyPanel(page);
    const listed = page.getByTestId('study-list').locator(`li[data-study="${id}"]`);
    await expect(listed).toContainText('gain map');
    await listed.getByRole('button').click();
    await expect(progress).toHaveAttribute('data-state', 'done', { timeout: 120_000 });
    await expect(progress).toHaveAttribute('data-done', '48');
    await expect(page.getByTestId('study-results-table')).toHaveAttribute('data-rows', '48');

    const heatMap = page.getByTestId('heat-map');
    await expect(heatMap).toBeVisible();
    await expect(heatMap).toHaveAttribute('data-cells', '48');
    await expect(heatMap).toHaveAttribute('data-filled', '48');
    await expect(page.getByTestId('heat-map-x')).toHaveValue('GainI.k');
    await expect(page.getByTestId('heat-map-y')).toHaveValue('GainP.k');
    // the table sorts by a column's header
    const table = page.getByTestId('study-results-table');
    await table.getByRole('button', { name: 'Position_Sensor#out#Value:max' }).click();
    await expect(table.locator('th[data-column="Position_Sensor#out#Value:max"]')).toHaveAttribute('aria-sort', 'ascending');
    await page.getByTestId('heat-map-output').selectOption('Position_Sensor#out#Value:max');
    await dialog.screenshot({ path: `${docsScreenshots}study-heat-map.png` });
});

test('an optimisation\'s best point is applied to the model as one step and undone', async ({ page, request }) => {
    await login(page, 'alice');
    const modelId = await openExample(page, 'Position Servo');
    await runAndWait(page);   // the objective's preview is computed on this run
    const before = { p: await modelParameter(page, 'GainP', 'k#Value'), i: await modelParameter(page, 'GainI', 'k#Value') };
    expect(before).toEqual({ p: '0.0264249', i: '0.000672426' });

    const dialog = await openStudyPanel(page);
    await page.getByTestId('study-kind-optimise').check();
    await addParameter(page, 'GainP.k', { from: '0.005', to: '0.05' });
    await addParameter(page, 'GainI.k', { from: '0', to: '0.002' });
    await page.getByTestId('objective-add-term').click();
    await dialog.getByLabel('Function').selectOption('ise');
    await page.getByTestId('objective-variable').fill('Position_Sensor#out#Value');
    await dialog.getByLabel('Reference variable').fill('Step#out#Value');
    await page.getByTestId('study-max-evaluations').fill('40');
    await dialog.getByLabel('Log samples').fill('500');
    const preview = page.getByTestId('objective-preview');
    await expect(preview).toHaveAttribute('data-state', 'value');
    await expect(preview).toContainText('Objective on the latest run');

    await page.getByTestId('study-start').click();
    const progress = page.getByTestId('study-progress');
    await expect(progress).toHaveAttribute('data-state', 'done', { timeout: 120_000 });
    await expect(page.getByTestId('convergence-plot').locator('canvas').first()).toBeVisible();
    const studies = await api<{ studies: Study[] }>(request, page, '/studies');
    const study = studies.studies.find((s) => s.kind === 'optimise' && s.model_id === modelId)!;
    const best = study.summary.best!;
    expect(Object.keys(best.parameters).sort()).toEqual(['GainI.k', 'GainP.k']);
    await expect(page.getByTestId('study-best')).toContainText(`run ${best.run}`);
    await dialog.screenshot({ path: `${docsScreenshots}study-convergence.png` });

    await page.getByTestId('apply-best').click();
    await expect.poll(() => modelParameter(page, 'GainP', 'k#Value')).toBe(String(best.parameters['GainP.k']));
    await expect.poll(() => modelParameter(page, 'GainI', 'k#Value')).toBe(String(best.parameters['GainI.k']));
    await page.getByTestId('study-close').click();
    await expect(dialog).toBeHidden();
    await expect(page.getByTestId('undo')).toHaveAttribute('title', `Undo Apply best point of study ${study.id} (Ctrl+Z)`);
    // one undo takes both values back
    await page.getByTestId('undo').click();
    await expect.poll(() => modelParameter(page, 'GainP', 'k#Value')).toBe(before.p);
    await expect.poll(() => modelParameter(page, 'GainI', 'k#Value')).toBe(before.i);
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
});

test('a sensitivity study draws the bands of its output over time', async ({ page }) => {
    await login(page, 'bob');
    await openExample(page, 'Position Servo');
    const dialog = await openStudyPanel(page);
    await page.getByTestId('study-kind-sensitivity').check();
    await addParameter(page, 'GainP.k', { mean: '0.0264249', sd: '0.006' });
    await addParameter(page, 'Mass.m', {});
    await addOutput(page, 'Position_Sensor#out#Value');
    await page.getByTestId('study-runs').fill('30');
    await dialog.getByLabel('Log samples').fill('300');
    await page.getByTestId('study-start').click();
    const progress = page.getByTestId('study-progress');
    await expect(progress).toHaveAttribute('data-state', 'done', { timeout: 120_000 });
    await expect(progress).toHaveAttribute('data-done', '30');
    const bands = page.getByTestId('bands-plot');
    await expect(bands).toHaveCount(1);
    await expect(bands).toContainText('Position_Sensor#out#Value: mean ±1σ, ±2σ over 30 runs');
    await expect(bands.locator('canvas').first()).toBeVisible();
    await expect(page.getByTestId('study-correlations')).toContainText('GainP.k');
    await bands.scrollIntoViewIfNeeded();
    await dialog.screenshot({ path: `${docsScreenshots}study-sensitivity-bands.png` });
});

test('a running 1-D sweep draws its curves, is cancelled, resumed, cancelled again and deleted', async ({ page }) => {
    await login(page, 'bob');
    await openExample(page, 'Position Servo');
    const dialog = await openStudyPanel(page);
    await addParameter(page, 'Mass.m', { from: '50', to: '500', steps: '300' });
    await addOutput(page, 'Position_Sensor#out#Value');
    await dialog.getByLabel('Stop time [s]').fill('10');
    await dialog.getByLabel('Log samples').fill('200');
    await page.getByTestId('study-start').click();
    const progress = page.getByTestId('study-progress');
    await expect.poll(async () => Number(await progress.getAttribute('data-done')), { timeout: 60_000 }).toBeGreaterThanOrEqual(3);
    await expect(page.getByTestId('sweep-curves').locator('canvas').first()).toBeVisible();
    const id = await page.getByTestId('study-list').locator('li.chosen').getAttribute('data-study');

    await page.getByTestId('study-cancel').click();
    await expect(progress).toHaveAttribute('data-state', 'cancelled', { timeout: 30_000 });
    const done = Number(await progress.getAttribute('data-done'));
    expect(done).toBeLessThan(300);
    await page.getByTestId('study-resume').click();
    await expect(progress).not.toHaveAttribute('data-state', 'cancelled');
    await page.getByTestId('study-cancel').click();
    await expect(progress).toHaveAttribute('data-state', 'cancelled', { timeout: 30_000 });
    expect(Number(await progress.getAttribute('data-done'))).toBeGreaterThanOrEqual(done);

    await page.getByTestId('study-delete').click();
    await expect(page.getByTestId('study-form')).toBeVisible();
    await expect(page.getByTestId('study-list').locator(`li[data-study="${id}"]`)).toHaveCount(0);
});
