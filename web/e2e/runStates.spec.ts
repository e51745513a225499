// Issue 38 item 6: the run status tells what became of a run. A run the server refuses names
// the server's reason until the next run starts; a number that is not finite never leaves the
// parameter panel; a run a component of the model ends as designed is a normal finish.
import { test, expect } from './fixtures';
import { login, openExample, runAndWait, setRunField } from './helpers';

const SERVO = 'Position Servo';

test('a refused run shows its reason', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const job = await runAndWait(page);
    const status = page.getByTestId('run-status');
    await expect(status).toHaveText(new RegExp(`^Job ${job}: done`));

    // 1e9 s in steps of a millisecond is far beyond the server's step limit (--max-steps)
    await setRunField(page, 'Time step', '0.001');
    await setRunField(page, 'Stop time', '1e9');
    await page.getByTestId('run').click();
    await expect(status).toHaveAttribute('data-state', 'not-started');
    await expect(status).toHaveText(/^Not started: the job needs .* steps; the limit is \d+ \(--max-steps\)$/);
    await expect(status).not.toHaveAttribute('data-job');
    // still there once the error toast has gone: the status does not go back to the last run
    await expect(page.locator('.toast-error')).toHaveCount(0, { timeout: 15_000 });
    await expect(status).toHaveText(/^Not started: the job needs/);

    await setRunField(page, 'Stop time', '1');
    const next = await runAndWait(page);
    expect(next).toBeGreaterThan(job);
    await expect(status).toHaveText(`Job ${next}: done`);
});

test('1e400 is refused in the parameter panel', async ({ page }) => {
    const sent: string[] = [];
    page.on('websocket', (ws) => ws.on('framesent', ({ payload }) => { if (typeof payload === 'string') sent.push(payload); }));
    await login(page, 'alice');
    await openExample(page, SERVO);
    await page.locator('.canvas .component[data-name="Mass"] .icon-frame').click();
    const mass = page.getByLabel('m value', { exact: true });
    await expect(mass).toHaveValue('100');

    for (const text of ['1e400', 'nan', '-inf']) {
        await mass.fill(text);
        await mass.press('Enter');
        await expect(page.locator('.parameter-panel .field-error')).toHaveText(`Mass.m: '${text}' is not a finite number`);
        await expect(page.getByLabel('m value', { exact: true })).toHaveAttribute('aria-invalid', 'true');
    }
    // nothing was sent: the model keeps its value and has nothing to save or undo
    expect(sent.filter((m) => m.includes('"parameter.set"'))).toEqual([]);
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
    await expect(page.getByTestId('undo')).toBeDisabled();
    const stored = await page.evaluate(() => {
        const app = (window as unknown as { __tlmhub: { store: { system: { components: { name: string; parameters: { name: string; value: string }[] }[] } } } }).__tlmhub;
        return app.store.system.components.find((c) => c.name === 'Mass')!.parameters.find((p) => p.name === 'm')!.value;
    });
    expect(stored).toBe('100');

    // a finite value is taken as before
    await page.getByLabel('m value', { exact: true }).fill('120');
    await page.getByLabel('m value', { exact: true }).press('Enter');
    await expect(page.locator('.parameter-panel .field-error')).toHaveCount(0);
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'true');
});

// Needs the server to report a run SignalStopSimulation ended as done with stop_reason.
test('F16InterceptMission ends as a normal finish', async ({ page }) => {
    test.setTimeout(180_000);
    await login(page, 'alice');
    await openExample(page, 'F16InterceptMission');
    const status = page.getByTestId('run-status');
    await page.getByTestId('run').click();
    await expect(status).toHaveAttribute('data-state', /^(done|failed|cancelled)$/, { timeout: 150_000 });
    const job = await status.getAttribute('data-job');
    await expect(status).toHaveText(`Job ${job}: done — Simulation stopped by Stop_simulation`);

    // the run history keeps the reason: after a reload the status says the same
    await page.reload();
    await expect(status).toHaveAttribute('data-job', job!);
    await expect(status).toHaveText(`Job ${job}: done — Simulation stopped by Stop_simulation`);
});
