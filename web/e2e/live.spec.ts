// Live mode on Position Servo (issue 42 item 3): a slider on the drawing bound to the step's
// amplitude, the model running in time with the clock, the plotted position following the
// slider, the cylinder moving with it, pause, step, keep as run, stop, a lost connection; the
// slider is part of the saved model.
import { copyFileSync, mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect } from './fixtures';
import { login, openExample, plotted, plotVariable, setRunField } from './helpers';
import type { Page } from '@playwright/test';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

const modelTime = (page: Page) => page.evaluate(() =>
    (window as unknown as { __tlmhub: { live: { session: { status: { modelTime: number } } } } }).__tlmhub.live.session.status.modelTime);
const last = async (page: Page, name: string) => (await plotted(page, name)).at(-1) ?? Number.NaN;
const CYLINDER = 'Cylinder_C#P3#Position';
const streamed = (page: Page, name: string) => page.evaluate((n) =>
    (window as unknown as { __tlmhub: { live: { session: { started: { variables: string[] } } } } }).__tlmhub.live.session.started.variables.includes(n), name);
const cylinderShift = (page: Page) => page.locator('.animation-parts[data-component="Cylinder_C"] .movable-part').first().getAttribute('transform');

test('live Position Servo: a slider on the drawing steers the running model; pause, step, keep as run, stop, a lost connection; the slider is saved', async ({ page }) => {
    // the variables live.start asks for, as sent
    let asked: string[] = [];
    page.on('websocket', (ws) => ws.on('framesent', ({ payload }) => {
        if (typeof payload === 'string' && payload.includes('"live.start"')) asked = (JSON.parse(payload) as { variables: string[] }).variables;
    }));
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const position = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    const reference = await plotVariable(page, 'Step', 'out', 'Value');

    // a slider for the step's amplitude, from the component's context menu
    await page.locator('.canvas .component[data-name="Step"] .icon-frame').click({ button: 'right' });
    await page.getByRole('menuitem', { name: 'Add live control…' }).click();
    const dialog = page.getByTestId('live-control-dialog');
    await dialog.getByLabel('Value it sets').fill('Step.y_A');
    await dialog.getByLabel('Kind').selectOption('slider');
    await dialog.getByLabel('Min').fill('0');
    await dialog.getByLabel('Max').fill('1');
    await dialog.getByTestId('live-control-ok').click();
    const slider = page.locator('[data-testid="live-control"][data-name="Step.y_A"]');
    await expect(slider).toBeVisible();
    // inert while editing
    await expect(slider.getByTestId('live-control-input')).toBeDisabled();

    // live runs the stored model: a longer stop time than its 3 s, saved (as alice's copy) with the slider
    await setRunField(page, 'Stop time', '60');
    await page.getByLabel('Stop time', { exact: true }).press('Enter');
    await page.getByTestId('save').click();
    await expect(page.getByTestId('save')).toHaveText('Save');
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');

    await expect(page.getByTestId('live-speed')).toHaveValue('1');
    await page.getByTestId('live').click();
    await expect(page.getByTestId('live-status')).toContainText('Live');
    const input = slider.getByTestId('live-control-input');
    await expect(input).toBeEnabled();
    // the step (t = 1 s) has come and the position has followed it up
    await expect.poll(() => modelTime(page), { timeout: 20_000 }).toBeGreaterThan(2);
    expect(await last(page, reference)).toBeCloseTo(0.7, 6);
    // the toast of the save has gone (it would hide the plot in the screenshot)
    await expect(page.locator('.toast')).toHaveCount(0);
    const before = await last(page, position);
    const cylinderBefore = await cylinderShift(page);

    // drag the slider to its low end: the step's amplitude 0, the reference back at 0.2
    const box = (await input.boundingBox())!;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + 1, box.y + box.height / 2, { steps: 6 });
    await page.mouse.up();
    await expect.poll(() => last(page, reference), { timeout: 10_000 }).toBeCloseTo(0.2, 6);
    // the position moves toward the new reference
    await expect.poll(() => last(page, position), { timeout: 15_000 }).toBeLessThan(before - 0.25 * (before - 0.2));
    mkdirSync(screenshots, { recursive: true });
    mkdirSync(docsScreenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}live-position-servo.png` });
    copyFileSync(`${screenshots}live-position-servo.png`, `${docsScreenshots}live-position-servo.png`);
    // the animation's variables are asked for and streamed, and the piston moves
    expect(asked).toContain(CYLINDER);
    expect(await streamed(page, CYLINDER)).toBe(true);
    await expect.poll(() => cylinderShift(page), { timeout: 10_000 }).not.toBe(cylinderBefore);

    // pause, then one step: a display frame of model time
    await page.getByTestId('live-pause').click();
    await expect(page.getByTestId('live-status')).toContainText('Paused');
    const paused = await modelTime(page);
    await page.getByTestId('live-step').click();
    await expect.poll(() => modelTime(page)).toBeGreaterThan(paused);
    expect(await modelTime(page)).toBeLessThan(paused + 0.1);
    await page.getByTestId('live-pause').click();
    await expect(page.getByTestId('live-status')).toContainText('Live');

    // keep as a run: the history lists it
    await page.getByTestId('live-record').click();
    await expect(page.locator('.history-row', { hasText: 'live session' })).toHaveCount(1, { timeout: 15_000 });

    await page.getByTestId('live-stop').click();
    await expect(page.getByTestId('live')).toBeVisible();
    await expect(page.getByTestId('live-message')).toContainText('Stopped at t =');
    await expect(input).toBeDisabled();

    // the recorded run plays back with the slider's changes marked on its timeline; a mark goes to its change
    await page.locator('.history-row', { hasText: 'live session' }).locator('.history-play').click();
    // (marks of changes close in time overlap: the last one is on top)
    const mark = page.getByTestId('playback-change').last();
    await expect(mark).toHaveAttribute('title', /^Step\.y_A = [\d.e-]+ at [\d.]+ s$/);
    const markedAt = /at ([\d.]+) s$/.exec((await mark.getAttribute('title'))!)![1];
    await mark.click();
    await expect(page.getByTestId('playback-time')).toContainText(`${markedAt} s /`);
    await page.screenshot({ path: `${docsScreenshots}playback-live-changes.png` });
    await page.getByTestId('playback-close').click();

    // a lost connection ends the session (the server ends it with its socket); live again once reconnected
    await page.getByTestId('live').click();
    await expect(page.getByTestId('live-status')).toContainText('Live');
    await page.evaluate(() => (window as unknown as { __tlmhub: { ws: { dropForTest(): void } } }).__tlmhub.ws.dropForTest());
    await expect(page.getByTestId('live-message')).toContainText('connection to the server was lost');
    await expect(input).toBeDisabled();
    await expect(page.getByTestId('connection-status')).toHaveAttribute('data-state', 'connected', { timeout: 30_000 });
    await page.getByTestId('live').click();
    await expect(page.getByTestId('live-status')).toContainText('Live');
    await expect(input).toBeEnabled();

    // the slider is part of the saved copy
    await page.reload();
    await expect(page.locator('[data-testid="live-control"][data-name="Step.y_A"]')).toBeVisible();
});
