// Logged in as bob: alice's own model list must stay empty for app.spec.
// Issue 13.2: a new model runs with its defaults (Hopsan's: 0 to 10 s, 1e-3 s step, 2048
// samples); a wrong run setting is explained next to its field, once, and cleared when fixed.
import { test, expect } from './fixtures';
import { login, runAndWait, setRunField } from './helpers';

test('a new model runs with the defaults; a wrong field is explained next to it', async ({ page }) => {
    await login(page, 'bob');
    await page.locator('input[name="new-model-name"]').fill('Fresh model');
    await page.getByRole('button', { name: 'Create' }).click();
    await expect(page.getByTestId('model-name')).toHaveText('Fresh model');
    await expect(page.getByLabel('Start time', { exact: true })).toHaveValue('0');
    await expect(page.getByLabel('Time step', { exact: true })).toHaveValue('0.001');
    await expect(page.getByLabel('Stop time', { exact: true })).toHaveValue('10');
    await expect(page.getByLabel('Log samples', { exact: true })).toHaveValue('2048');

    // something to simulate: a sine source from the palette
    await page.getByLabel('Search components').fill('SignalSineWave');
    await page.locator('.palette-item[data-type="SignalSineWave"]').dblclick();
    await expect(page.locator('.canvas .component').first()).toBeVisible();
    await runAndWait(page);
    await expect(page.getByTestId('run-status')).toHaveAttribute('data-state', 'done');

    // a wrong value: one message in words next to the field, no schema path, no run, no toast
    const samples = page.getByLabel('Log samples', { exact: true });
    await setRunField(page, 'Log samples', '0');
    const error = page.locator('#run-log_samples-error');
    await expect(error).toHaveText('Log samples must be a whole number of at least 1.');
    await expect(samples).toHaveAttribute('aria-invalid', 'true');
    await page.getByTestId('run').click();
    // the status tells why no run started, and names no run until the next one starts
    await expect(page.getByTestId('run-status')).toContainText('correct the marked field');
    await expect(page.getByTestId('run-status')).toHaveAttribute('data-state', 'not-started');
    await expect(page.getByTestId('run-status')).not.toHaveAttribute('data-job');
    await expect(page.locator('.run-panel .field-error:not([hidden])')).toHaveCount(1);
    await expect(page.locator('#toasts .toast')).toHaveCount(0);
    await page.locator('.run-panel').screenshot({ path: 'e2e/screenshots/run-field-error.png' });
    await expect(page.locator('body')).not.toContainText('message.log_samples');

    await setRunField(page, 'Log samples', '500');
    await expect(error).toBeHidden();
    await expect(samples).toHaveAttribute('aria-invalid', 'false');
    await runAndWait(page);
});
