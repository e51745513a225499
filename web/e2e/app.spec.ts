// The app in a real browser against the real server: log in, open the Position Servo example,
// draw it, run it with a live plot, edit, connect, save, and access rules.
import { copyFileSync, mkdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect } from './fixtures';
import {
    api, baseUrl, dragPortToPort, login, openExample, plotted, plotVariable, port, runAndWait, setRunField,
} from './helpers';
import type { Model, ResultsJson } from '../src/protocol/types';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));
const SERVO = 'Position Servo';

test('logs in and lists the examples', async ({ page }) => {
    await login(page, 'alice');
    await expect(page.getByTestId('user')).toHaveText('alice (user)');
    await expect(page.getByTestId('example-models').getByRole('link', { name: SERVO, exact: true })).toBeVisible();
    await expect(page.getByTestId('own-models')).toContainText('None yet');
});

test('a wrong password is refused with the server message', async ({ page }) => {
    await page.goto(`${baseUrl()}/#/login`);
    await page.getByLabel('User name').fill('alice');
    await page.getByLabel('Password').fill('not-her-password');
    await page.getByRole('button', { name: 'Log in' }).click();
    await expect(page.locator('.login-form [role="alert"]')).not.toBeEmpty();
    await expect(page.getByRole('heading', { name: 'Examples' })).toHaveCount(0);
});

test('opens Position Servo and draws every component and connection', async ({ page, request }) => {
    await login(page, 'alice');
    const id = await openExample(page, SERVO);
    const { model } = await api<{ model: Model }>(request, page, `/models/${id}`);
    const components = model.system.components;
    expect(components.length).toBeGreaterThan(10);
    await expect(page.locator('.canvas .component:not(.system-port)')).toHaveCount(components.length);
    for (const c of components) await expect(page.locator(`.canvas .component[data-name="${c.name}"]`)).toBeVisible();
    await expect(page.locator('.canvas .connection')).toHaveCount(model.system.connections.length);
    for (const c of model.system.connections) {
        await expect(page.locator(`.canvas .connection[data-from="${c.from.component}.${c.from.port}"][data-to="${c.to.component}.${c.to.port}"]`)).toHaveCount(1);
    }
    // components sit where the author put them: left-to-right order of two known ones
    const step = await page.locator('.canvas .component[data-name="Step"]').boundingBox();
    const mass = await page.locator('.canvas .component[data-name="Mass"]').boundingBox();
    const poseOf = (name: string) => components.find((c) => c.name === name)!.pose;
    expect(Math.sign(mass!.x - step!.x)).toBe(Math.sign(poseOf('Mass').x - poseOf('Step').x));
    mkdirSync(screenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}editor.png` });
    mkdirSync(docsScreenshots, { recursive: true });
    copyFileSync(`${screenshots}editor.png`, `${docsScreenshots}editor.png`);
});

test('runs Position Servo: the plot fills while running and ends on the stored result', async ({ page, request }) => {
    // The app asks for binary frames: no event.frame comes as JSON text.
    let binaryFrames = 0, textFrames = 0;
    page.on('websocket', (ws) => ws.on('framereceived', ({ payload }) => {
        if (typeof payload !== 'string') binaryFrames++;
        else if (payload.includes('"event.frame"')) textFrames++;
    }));
    await login(page, 'alice');
    await openExample(page, SERVO);
    const variable = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    expect(variable).toBe('Position_Sensor#out#Value');
    // a long run (10^7 steps) so that the plot is seen while it grows
    await setRunField(page, 'Stop time', '1000');
    await page.getByTestId('run').click();
    const plot = page.locator('.plot-window').first();
    await page.waitForFunction(() => {
        const status = document.querySelector('[data-testid="run-status"]') as HTMLElement | null;
        const plotEl = document.querySelector('.plot-window') as HTMLElement | null;
        return status?.dataset.state === 'running' && Number(plotEl?.dataset.points ?? 0) > 10;
    }, undefined, { timeout: 30_000 });
    const pointsWhileRunning = Number(await plot.getAttribute('data-points'));
    await expect(page.locator('.plot-window canvas').first()).toBeVisible();
    // a fuller picture for the screenshot, if the run is still going
    await page.waitForFunction(() => {
        const bar = document.querySelector('.run-panel progress') as HTMLProgressElement | null;
        const status = document.querySelector('[data-testid="run-status"]') as HTMLElement | null;
        return (bar?.value ?? 0) >= 0.35 || status?.dataset.state !== 'running';
    }, undefined, { timeout: 20_000 }).catch(() => undefined);
    mkdirSync(screenshots, { recursive: true });
    mkdirSync(docsScreenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}live-plot.png` });
    copyFileSync(`${screenshots}live-plot.png`, `${docsScreenshots}editor-live-plot.png`);

    const status = page.getByTestId('run-status');
    await expect(status).toHaveAttribute('data-state', 'done', { timeout: 60_000 });
    const job = Number(await status.getAttribute('data-job'));
    const results = await api<ResultsJson>(request, page, `/jobs/${job}/results?format=json&variables=${encodeURIComponent(variable)}`);
    const stored = results.variables.find((v) => v.name === variable)!.data;
    await expect.poll(async () => (await plotted(page, variable)).length).toBe(stored.length);
    expect(pointsWhileRunning).toBeLessThan(stored.length);
    const shown = await plotted(page, variable);
    expect(shown[shown.length - 1]).toBe(stored[stored.length - 1]);
    expect(shown).toEqual(stored);
    expect(binaryFrames).toBeGreaterThan(0);
    expect(textFrames).toBe(0);

    // export: CSV of the plotted data, PNG of the plot
    const [csv] = await Promise.all([page.waitForEvent('download'), plot.getByRole('button', { name: 'CSV', exact: true }).click()]);
    const lines = readFileSync(await csv.path(), 'utf8').trim().split('\n');
    expect(lines[0]).toBe(`time,${variable}`);
    expect(lines).toHaveLength(stored.length + 1);
    expect(Number(lines[lines.length - 1].split(',')[1])).toBe(stored[stored.length - 1]);
    const [png] = await Promise.all([page.waitForEvent('download'), plot.getByRole('button', { name: 'PNG' }).click()]);
    expect(png.suggestedFilename()).toMatch(/\.png$/);
    expect(readFileSync(await png.path()).subarray(1, 4).toString()).toBe('PNG');
});

test('a running simulation can be cancelled', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    await setRunField(page, 'Stop time', '4000');
    await page.getByTestId('run').click();
    const status = page.getByTestId('run-status');
    await expect(status).toHaveAttribute('data-state', 'running');
    await page.getByTestId('cancel').click();
    await expect(status).toHaveAttribute('data-state', 'cancelled', { timeout: 30_000 });
    await expect(page.getByTestId('run')).toBeEnabled();
});

test('a changed parameter changes the plot of the next run; bad values are refused inline', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const variable = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    await runAndWait(page);
    // The plot redraws at the next animation frame; a short run's frames can come with its end.
    await expect.poll(async () => (await plotted(page, variable)).length).toBeGreaterThan(100);
    const first = await plotted(page, variable);

    await page.locator('.canvas .component[data-name="GainP"] .icon-frame').click();
    const gain = page.getByLabel('k#Value value');
    await gain.fill('no_such_name');
    await gain.press('Enter');
    await expect(page.locator('.parameter-panel .field-error')).toBeVisible();
    await expect(gain).toHaveAttribute('aria-invalid', 'true');
    await gain.fill('0.005');
    await gain.press('Enter');
    await expect(page.locator('.parameter-panel .field-error')).toHaveCount(0);
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'true');

    await runAndWait(page);
    await expect.poll(async () => {
        const second = await plotted(page, variable);
        return second.length === first.length && second[second.length - 1] !== first[first.length - 1];
    }, { message: 'the second run is plotted, with another end value' }).toBe(true);
    // compare with the previous run: its series is the first run's data
    await page.locator('.plot-window input[name="compare"]').first().check();
    await expect.poll(async () => (await plotted(page, variable, true)).length).toBe(first.length);
    expect(await plotted(page, variable, true)).toEqual(first);
});

test('adds a component from the palette and connects it; an illegal connection shows the reason', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    await page.getByLabel('Search components').fill('SignalGain');
    const item = page.locator('.palette-item[data-type="SignalGain"]');
    const canvas = page.getByTestId('canvas');
    const box = (await canvas.boundingBox())!;
    await item.dragTo(canvas, { targetPosition: { x: 80, y: box.height - 80 } });
    const added = page.locator('.canvas .component[data-name="Gain"]');
    await expect(added).toBeVisible();
    await expect(page.getByLabel('Component name')).toHaveValue('Gain');

    await dragPortToPort(page, ['Position_Sensor', 'out'], ['Gain', 'in']);
    await expect(page.locator('.canvas .connection[data-from="Position_Sensor.out"][data-to="Gain.in"]')).toHaveCount(1);
    await expect(port(page, 'Gain', 'in')).toHaveClass(/connected/);

    // two outputs cannot be joined: the core's reason appears in the message area, the port is marked
    await dragPortToPort(page, ['Gain', 'out'], ['Step', 'out']);
    const bubble = page.getByTestId('editor-messages').getByRole('alert');
    await expect(bubble).toBeVisible();
    await expect(page.locator('.canvas .port-error-mark')).toBeVisible();
    await expect(bubble).toContainText('Gain');
    await expect(bubble).toContainText('Step');
    await expect(page.locator('.canvas .connection[data-from="Gain.out"]')).toHaveCount(0);

    // undo takes the connection back out
    await page.getByTestId('undo').click();
    await expect(page.locator('.canvas .connection[data-to="Gain.in"]')).toHaveCount(0);
});

test('save keeps the change after a reload, and another user cannot open the model', async ({ page, browser, request }) => {
    await login(page, 'alice');
    const exampleId = await openExample(page, SERVO);
    await page.getByLabel('Search components').fill('SignalGain');
    await page.locator('.palette-item[data-type="SignalGain"]').dblclick();
    await expect(page.locator('.canvas .component[data-name="Gain"]')).toBeVisible();
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'true');
    // a run setting becomes the model's own and is saved with it
    await setRunField(page, 'Stop time', '4.5');
    await page.getByLabel('Stop time', { exact: true }).press('Tab');
    await page.getByTestId('save').click();
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
    await expect.poll(() => page.url()).not.toContain(`#/model/${exampleId}`);
    const ownId = Number(/#\/model\/(\d+)/.exec(page.url())![1]);

    await page.reload();
    await expect(page.locator('.canvas .component[data-name="Gain"]')).toBeVisible();
    const { model } = await api<{ model: Model }>(request, page, `/models/${ownId}`);
    expect(model.system.components.some((c) => c.name === 'Gain' && c.type === 'SignalGain')).toBe(true);
    expect(model.system.simulation?.stop).toBe(4.5);
    await expect(page.getByLabel('Stop time', { exact: true })).toHaveValue('4.5');
    // the example itself is unchanged
    const example = await api<{ model: Model }>(request, page, `/models/${exampleId}`);
    expect(example.model.system.components.some((c) => c.name === 'Gain')).toBe(false);

    const other = await browser.newContext();
    const bob = await other.newPage();
    await login(bob, 'bob');
    await expect(bob.locator(`tr[data-model-id="${ownId}"]`)).toHaveCount(0);
    await bob.goto(`${baseUrl()}/#/model/${ownId}`);
    await expect(bob.getByTestId('open-error')).toContainText('not found');
    await other.close();
});

test('groups a selection into a subsystem that can be entered and still runs', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    await page.locator('.canvas .component[data-name="GainP"] .icon-frame').click();
    await page.locator('.canvas .component[data-name="Add"] .icon-frame').click({ modifiers: ['Shift'] });
    await expect(page.locator('.parameter-panel h2')).toHaveText('2 components selected');
    await page.getByTestId('group').click();
    const sub = page.locator('.canvas .component.subsystem[data-name="Subsystem"]');
    await expect(sub).toBeVisible();
    await expect(page.locator('.canvas .component[data-name="GainP"]')).toHaveCount(0);
    // an ordinary edit: nothing is saved (an example stays the example)
    await expect(page.getByTestId('save')).toHaveText('Save as my copy');

    await sub.locator('.icon-frame').dblclick();
    await expect(page.locator('.breadcrumb')).toContainText('Subsystem');
    await expect(page.locator('.canvas .component[data-name="GainP"]')).toBeVisible();
    await expect(page.locator('.canvas .component[data-name="Add"]')).toBeVisible();
    await expect(page.locator('.canvas .system-port')).toHaveCount(3);
    await page.locator('.breadcrumb .crumb').first().click();
    await expect(sub).toBeVisible();

    await runAndWait(page);
    await expect(page.getByTestId('run-status')).toHaveAttribute('data-state', 'done');
});
