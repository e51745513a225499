// Parameter ports (a component's settable inputs without a place on Hopsan's icon) stay hidden
// unless shown, so that pressing a power port of Position Servo's valves always gets that port.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { expect, test, type Page } from './fixtures';
import { login, openExample, port } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));
const SERVO = 'Position Servo';
const VALVE = '4_3_Servo_Valve';
const RELIEF = 'Pressure_Relief_Valve';
// larger pictures for the docs; pointer positions stay in CSS pixels
test.use({ deviceScaleFactor: 2 });

const POWER_PORTS: [string, string][] = [[VALVE, 'PP'], [VALVE, 'PT'], [VALVE, 'PA'], [VALVE, 'PB'], [RELIEF, 'P1'], [RELIEF, 'P2']];

/** Presses the middle of a port's marker, where a person aims, and lets the page decide what was hit. */
async function clickPortCentre(page: Page, component: string, portName: string): Promise<void> {
    const box = await port(page, component, portName).boundingBox();
    if (!box) throw new Error(`port not visible: ${component}.${portName}`);
    await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
}

/** Both valves with some room around them. */
async function valvesArea(page: Page) {
    const boxes = await Promise.all([VALVE, RELIEF].map((name) => page.locator(`.canvas .component[data-name="${name}"]`).boundingBox()));
    const [x0, y0] = [Math.min(...boxes.map((b) => b!.x)) - 60, Math.min(...boxes.map((b) => b!.y)) - 60];
    const [x1, y1] = [Math.max(...boxes.map((b) => b!.x + b!.width)) + 60, Math.max(...boxes.map((b) => b!.y + b!.height)) + 60];
    return { x: Math.max(0, x0), y: Math.max(0, y0), width: x1 - Math.max(0, x0), height: y1 - Math.max(0, y0) };
}

test('every power port of the servo valve and the relief valve opens its own variables, never a parameter port\'s', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const title = page.locator('.variable-picker .picker-title');
    for (const [component, portName] of POWER_PORTS) {
        // hovering or selecting the valve no longer brings its parameter ports over the power ports
        await page.locator(`.canvas .component[data-name="${component}"] .icon-frame`).hover();
        await clickPortCentre(page, component, portName);
        await expect(title).toHaveText(`Plot ${component}.${portName}`);
        await expect(page.locator('.variable-picker [role="menuitem"]').first()).toBeVisible();
    }
    await expect(port(page, VALVE, 'x_pb')).toBeHidden();
    await expect(port(page, RELIEF, 'tao')).toBeHidden();
});

test('the toolbar switch shows every parameter port and hides them again', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const toggle = page.getByTestId('show-parameter-ports');
    await expect(port(page, VALVE, 'x_pb')).toBeHidden();
    await expect(port(page, VALVE, 'in')).toBeVisible();
    mkdirSync(docsScreenshots, { recursive: true });
    await page.screenshot({ path: `${docsScreenshots}position-servo-parameter-ports-hidden.png`, clip: await valvesArea(page) });

    await toggle.click();
    await expect(toggle).toHaveAttribute('aria-pressed', 'true');
    await expect(port(page, VALVE, 'x_pb')).toBeVisible();
    await expect(port(page, RELIEF, 'tao')).toBeVisible();
    await page.screenshot({ path: `${docsScreenshots}position-servo-parameter-ports-shown.png`, clip: await valvesArea(page) });
    // shown, they still keep off the power ports
    await clickPortCentre(page, VALVE, 'PT');
    await expect(page.locator('.variable-picker .picker-title')).toHaveText(`Plot ${VALVE}.PT`);

    await toggle.click();
    await expect(toggle).toHaveAttribute('aria-pressed', 'false');
    await expect(port(page, VALVE, 'x_pb')).toBeHidden();
    await expect(port(page, RELIEF, 'tao')).toBeHidden();
});

test('one component\'s parameter ports are shown from the parameter panel or with P', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    await page.locator(`.canvas .component[data-name="${VALVE}"] .icon-frame`).click();
    const button = page.getByTestId('toggle-parameter-ports');
    await button.click();
    await expect(button).toHaveAttribute('aria-pressed', 'true');
    await expect(port(page, VALVE, 'x_pb')).toBeVisible();
    await expect(port(page, RELIEF, 'tao')).toBeHidden();

    await page.locator(`.canvas .component[data-name="${VALVE}"] .icon-frame`).click();
    await page.keyboard.press('p');
    await expect(port(page, VALVE, 'x_pb')).toBeHidden();
    await expect(page.getByTestId('toggle-parameter-ports')).toHaveAttribute('aria-pressed', 'false');
});

test('a dragged signal output shows the hidden parameter ports that can take it, and drops on one', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const target = port(page, RELIEF, 'p_max');
    await expect(target).toBeHidden();
    const from = (await port(page, 'Step', 'out').boundingBox())!;
    await page.mouse.move(from.x + from.width / 2, from.y + from.height / 2);
    await page.mouse.down();
    await page.mouse.move(from.x + 40, from.y + 40, { steps: 5 });
    await expect(target).toBeVisible();
    const to = (await target.boundingBox())!;
    await page.mouse.move(to.x + to.width / 2, to.y + to.height / 2, { steps: 5 });
    await page.mouse.up();
    await expect(page.locator(`.canvas .connection[data-from="Step.out"][data-to="${RELIEF}.p_max"]`)).toHaveCount(1);
    // connected, it stays; the others hide again
    await expect(target).toBeVisible();
    await expect(port(page, RELIEF, 'tao')).toBeHidden();
});
