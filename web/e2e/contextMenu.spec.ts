// Context menus on Position Servo (issue 39, item 2): a rotate and a delete from a component's
// menu, each undone with Ctrl+Z to the model as it was; a valve replaced by another type with
// the same power ports keeps its connections; the menu's keys; the help panel. And (item 9)
// a refused connection's reason in the message area over the canvas, in words, not clipped.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { expect, test, type Page } from './fixtures';
import { dragPortToPort, login, openExample, port } from './helpers';
import type { Model } from '../src/protocol/types';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));
const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const SERVO = 'Position Servo';
const VALVE = '4_3_Servo_Valve';
const RELIEF = 'Pressure_Relief_Valve';
/** The valve's six connections in Position Servo (its four power ports, its input and its xv output). */
const VALVE_LINES = [
    ['Hydraulic_Volume_Multi_Port.P1', `${VALVE}.PP`], ['Tank_C.P1', `${VALVE}.PT`], [`${VALVE}.PA`, 'Cylinder_C.P1'],
    [`${VALVE}.PB`, 'Cylinder_C.P2'], ['Add.out', `${VALVE}.in`], ['Sink.in', `${VALVE}.xv`],
];

/** The open model as the editor holds it, in an order-free form to compare. */
async function modelNow(page: Page): Promise<unknown> {
    const model = await page.evaluate(() => (window as unknown as { __tlmhub: { store: { model: Model } } }).__tlmhub.store.model);
    const system = model.system;
    return {
        components: system.components.map((c) => ({ name: c.name, type: c.type, pose: c.pose, parameters: c.parameters }))
            .sort((a, b) => a.name.localeCompare(b.name)),
        connections: system.connections.map((c) => [`${c.from.component}.${c.from.port}`, `${c.to.component}.${c.to.port}`].sort().join(' — ')).sort(),
    };
}

const component = (page: Page, name: string) => page.locator(`.canvas .component[data-name="${name}"]`);
const menuOf = (page: Page, name: string) => page.getByRole('menu', { name: `${name} menu` });
const entry = (page: Page, id: string) => page.locator(`.context-menu [data-entry="${id}"]`);

/** The drawn line between two ports, whichever way round it was connected. */
const lineOf = (page: Page, a: string, b: string) =>
    page.locator(`.canvas .connection[data-from="${a}"][data-to="${b}"], .canvas .connection[data-from="${b}"][data-to="${a}"]`);

async function lineCount(page: Page, a: string, b: string): Promise<number> {
    return lineOf(page, a, b).count();
}

test('a rotate and a delete from a component\'s context menu are each undone by Ctrl+Z to the model as it was', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const original = await modelNow(page);

    await component(page, VALVE).locator('.icon-frame').click({ button: 'right' });
    await expect(menuOf(page, VALVE)).toBeVisible();
    await expect(page.getByRole('menuitem', { name: /Parameters/ })).toBeFocused();
    await entry(page, 'rotate-right').click();
    await expect(menuOf(page, VALVE)).toHaveCount(0);
    await expect(component(page, VALVE).locator('.component-body')).toHaveAttribute('transform', /rotate\(90\)/);
    expect(await modelNow(page)).not.toEqual(original);
    await expect(page.getByTestId('undo')).toHaveAttribute('title', 'Undo Rotate right (Ctrl+Z)');
    await page.keyboard.press('Control+z');
    await expect(component(page, VALVE).locator('.component-body')).not.toHaveAttribute('transform', /rotate\(90\)/);
    await expect.poll(() => modelNow(page)).toEqual(original);

    await component(page, RELIEF).locator('.icon-frame').click({ button: 'right' });
    await entry(page, 'delete').click();
    await expect(component(page, RELIEF)).toHaveCount(0);
    expect(await lineCount(page, 'Hydraulic_Volume_Multi_Port.P1', `${RELIEF}.P1`)).toBe(0);
    await page.keyboard.press('Control+z');
    await expect(component(page, RELIEF)).toHaveCount(1);
    await expect.poll(() => modelNow(page)).toEqual(original);
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
});

test('the 4/3 valve replaced by one with neutral to tank keeps all its connections; undo brings the old type back', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const original = await modelNow(page);
    for (const [a, b] of VALVE_LINES) expect(await lineCount(page, a, b), `${a}–${b}`).toBe(1);

    await component(page, VALVE).locator('.icon-frame').click({ button: 'right' });
    await entry(page, 'replace').hover();
    const choice = entry(page, 'replace-Hydraulic43ValveNeutralToTank');
    await expect(choice).toBeVisible();
    await expect(choice).toHaveAttribute('title', /keeps all 6 connections/);
    // only types with the valve's power ports are offered
    await expect(page.locator('.context-menu [data-entry^="replace-"]')).toHaveCount(5);
    await choice.click();

    await expect(component(page, VALVE)).toHaveAttribute('data-type', 'Hydraulic43ValveNeutralToTank');
    for (const [a, b] of VALVE_LINES) await expect(lineOf(page, a, b), `${a}–${b}`).toHaveCount(1);
    await expect(page.getByTestId('undo')).toHaveAttribute('title', `Undo Replace ${VALVE} by Hydraulic43ValveNeutralToTank (Ctrl+Z)`);
    const replaced = await modelNow(page) as { connections: string[] };
    expect(replaced.connections).toEqual((original as { connections: string[] }).connections);
    // the parameters of the same name kept their values
    await component(page, VALVE).locator('.icon-frame').click();
    await expect(page.locator('.parameter-panel tr[data-param="omega_h"] input')).toHaveValue(
        ((original as { components: { name: string; parameters: { name: string; value: string }[] }[] }).components
            .find((c) => c.name === VALVE)!.parameters.find((p) => p.name === 'omega_h')!.value));

    await page.keyboard.press('Control+z');
    await expect(component(page, VALVE)).toHaveAttribute('data-type', 'Hydraulic43Valve');
    await expect.poll(() => modelNow(page)).toEqual(original);
});

test('the menu is worked with the keys, stays inside the window and closes on Escape or a click elsewhere', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const frame = component(page, VALVE).locator('.icon-frame');
    await frame.click();
    // Shift+F10 opens the selection's menu (Parameters…, Plot variables, Add live control…,
    // Rotate right, Rotate left, …); ↓ ↓ ↓ ↓ Enter: "Rotate left"
    await page.keyboard.press('Shift+F10');
    const menu = menuOf(page, VALVE);
    await expect(menu).toBeVisible();
    await expect(page.locator('.context-menu-item:focus')).toContainText('Parameters');
    for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowDown');
    await expect(page.locator('.context-menu-item:focus')).toContainText('Rotate left');
    await page.keyboard.press('Enter');
    await expect(component(page, VALVE).locator('.component-body')).toHaveAttribute('transform', /rotate\(270\)/);
    await page.keyboard.press('Control+z');
    await expect(component(page, VALVE).locator('.component-body')).not.toHaveAttribute('transform', /rotate\(270\)/);

    // Escape closes; the selection stays (the key went to the menu, not the editor)
    await frame.click({ button: 'right' });
    await expect(menu).toBeVisible();
    await page.keyboard.press('Escape');
    await expect(menu).toHaveCount(0);
    await expect(component(page, VALVE)).toHaveClass(/selected/);

    // a click elsewhere closes
    await frame.click({ button: 'right' });
    await expect(menu).toBeVisible();
    await page.locator('.parameter-panel').click({ position: { x: 150, y: 10 } });
    await expect(menu).toHaveCount(0);

    // opened at the window's bottom-right corner of the canvas, it stays inside the window
    const canvasBox = (await page.getByTestId('canvas').boundingBox())!;
    await page.mouse.click(canvasBox.x + canvasBox.width - 3, canvasBox.y + canvasBox.height - 3, { button: 'right' });
    const canvasMenu = page.getByRole('menu', { name: 'Canvas menu' });
    await expect(canvasMenu).toBeVisible();
    const box = (await canvasMenu.boundingBox())!;
    const viewport = page.viewportSize()!;
    expect(box.x).toBeGreaterThanOrEqual(0);
    expect(box.y).toBeGreaterThanOrEqual(0);
    expect(box.x + box.width).toBeLessThanOrEqual(viewport.width);
    expect(box.y + box.height).toBeLessThanOrEqual(viewport.height);
    // "Show all parameter ports" from the canvas's menu
    await expect(port(page, VALVE, 'x_pb')).toBeHidden();
    await entry(page, 'all-parameter-ports').click();
    await expect(port(page, VALVE, 'x_pb')).toBeVisible();
    await expect(page.getByTestId('show-parameter-ports')).toHaveAttribute('aria-pressed', 'true');
});

test('a port\'s menu plots its variables; a line\'s menu deletes it (undoable)', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const pa = port(page, VALVE, 'PA');
    const box = (await pa.boundingBox())!;
    await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2, { button: 'right' });
    await expect(page.getByRole('menu', { name: `${VALVE}.PA menu` })).toBeVisible();
    // the primary variables first
    await expect(page.locator('.context-menu-item').first()).toContainText(/Plot (Flow|Pressure)/);
    await entry(page, 'plot-Pressure').click();
    await expect.poll(() => page.evaluate(() => (window as unknown as { __tlmhub: { plots: { allVariables(): string[] } } }).__tlmhub.plots.allVariables()))
        .toContain(`${VALVE}#PA#Pressure`);

    const line = page.locator(`.canvas .connection[data-from="${VALVE}.PA"][data-to="Cylinder_C.P1"]`);
    const lineBox = (await line.boundingBox())!;
    // a point on the line: its first segment leaves the port
    const points = (await line.getAttribute('points'))!.split(' ').map((p) => p.split(',').map(Number));
    const mid = await page.evaluate(([[x0, y0], [x1, y1]]) => {
        const app = (window as unknown as { __tlmhub: { canvas: { clientFromScene(p: { x: number; y: number }): { x: number; y: number } } } }).__tlmhub;
        return app.canvas.clientFromScene({ x: (x0 + x1) / 2, y: (y0 + y1) / 2 });
    }, [points[0], points[1]]);
    expect(lineBox.width + lineBox.height).toBeGreaterThan(0);
    await page.mouse.click(mid.x, mid.y, { button: 'right' });
    await expect(page.getByRole('menu', { name: 'Connection menu' })).toBeVisible();
    await entry(page, 'delete').click();
    await expect(line).toHaveCount(0);
    await page.keyboard.press('Control+z');
    await expect(lineOf(page, `${VALVE}.PA`, 'Cylinder_C.P1')).toHaveCount(1);
});

test('the help panel lists the keys; a refused connection\'s reason is in words in the message area, not clipped; fields are labelled', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    await page.getByTestId('canvas').focus();
    await page.keyboard.press('?');
    const help = page.getByTestId('shortcut-help');
    await expect(help).toBeVisible();
    await expect(help.getByRole('heading', { name: 'Keyboard shortcuts' })).toBeVisible();
    await expect(help.locator('tr', { hasText: 'Rotate left' })).toContainText('Shift');
    mkdirSync(screenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}shortcut-help.png` });
    await page.keyboard.press('Escape');
    await expect(help).toBeHidden();
    await page.getByTestId('shortcuts-button').click();
    await expect(help).toBeVisible();
    await help.getByRole('button', { name: 'Close' }).click();
    await expect(help).toBeHidden();

    // a signal output dropped on a hydraulic port: refused, with the reason in words
    await dragPortToPort(page, ['Step', 'out'], [VALVE, 'PT']);
    const message = page.getByTestId('editor-messages').getByRole('alert');
    await expect(message).toContainText(`Cannot connect Step.out to ${VALVE}.PT`);
    await expect(message).toContainText('a signal port cannot be joined to a hydraulic port');
    await expect(page.locator('.canvas [role="alert"]')).toHaveCount(0);   // nothing drawn in the SVG
    await expect(page.locator('.canvas .port-error-mark')).toHaveCount(1);
    // all of it inside the window, nothing cut off
    const box = (await message.boundingBox())!;
    expect(box.x + box.width).toBeLessThanOrEqual(page.viewportSize()!.width);
    const clipped = await message.locator('.editor-message-text').evaluate((el) => el.scrollWidth > el.clientWidth + 1 || el.scrollHeight > el.clientHeight + 1);
    expect(clipped).toBe(false);
    await page.screenshot({ path: `${screenshots}editor-message.png` });
    await message.getByRole('button', { name: 'Dismiss the message' }).click();
    await expect(message).toHaveCount(0);

    // every form field of the editor has a label a screen reader reads (the parameter panel's too)
    await component(page, VALVE).locator('.icon-frame').click();
    const unlabelled = await page.locator('main.editor').evaluate((main) => [...main.querySelectorAll('input, select, textarea')]
        .filter((el) => (el as HTMLElement).offsetParent !== null && (el as HTMLInputElement).type !== 'hidden')
        .filter((el) => ((el as HTMLInputElement).labels?.length ?? 0) === 0 && !el.getAttribute('aria-label')?.trim() && !el.getAttribute('aria-labelledby'))
        .map((el) => el.outerHTML.slice(0, 120)));
    expect(unlabelled).toEqual([]);
});

test.describe('for the docs', () => {
    // a larger picture; pointer positions stay in CSS pixels
    test.use({ deviceScaleFactor: 2 });

    test('screenshot: a component\'s context menu with its "Replace with" list', async ({ page }) => {
        await login(page, 'alice');
        await openExample(page, SERVO);
        // pressed at the valve's lower right corner, so that the menu leaves the valve in sight
        const frame = component(page, VALVE).locator('.icon-frame');
        const size = (await frame.boundingBox())!;
        await frame.click({ button: 'right', position: { x: size.width - 4, y: size.height - 4 } });
        await entry(page, 'replace').hover();
        await expect(entry(page, 'replace-Hydraulic43ValveNeutralToTank')).toBeVisible();
        await entry(page, 'replace-Hydraulic43ValveNeutralToTank').hover();
        const boxes = await Promise.all([component(page, VALVE), ...await page.locator('.context-menu').all()].map((l) => l.boundingBox()));
        const x0 = Math.max(0, Math.min(...boxes.map((b) => b!.x)) - 40);
        const y0 = Math.max(0, Math.min(...boxes.map((b) => b!.y)) - 40);
        const x1 = Math.max(...boxes.map((b) => b!.x + b!.width)) + 20;
        const y1 = Math.max(...boxes.map((b) => b!.y + b!.height)) + 20;
        mkdirSync(docsScreenshots, { recursive: true });
        await page.screenshot({ path: `${docsScreenshots}context-menu.png`, clip: { x: x0, y: y0, width: x1 - x0, height: y1 - y0 } });
    });
});
