// Parameter ports (a component's settable inputs without a place on Hopsan's icon) stay hidden
// unless shown, so that pressing a power port of Position Servo's valves always gets that port.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { expect, test, type Page } from './fixtures';
import { dragPortToPort, login, openExample, port } from './helpers';
import type { System } from '../src/protocol/types';

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

/** The model's lines on a port, as `component.port` pairs (the port's own end first). */
async function linesOn(page: Page, component: string, portName: string): Promise<[string, string][]> {
    return page.evaluate(([c, p]) => {
        const { store } = (window as unknown as { __tlmhub: { store: { system: System } } }).__tlmhub;
        const name = (r: { component: string; port: string }) => `${r.component}.${r.port}`;
        return store.system.connections
            .filter((l) => name(l.from) === `${c}.${p}` || name(l.to) === `${c}.${p}`)
            .map((l) => (name(l.from) === `${c}.${p}` ? [name(l.from), name(l.to)] : [name(l.to), name(l.from)]) as [string, string]);
    }, [component, portName]);
}

/** A point of the line between ports `a` and `b` (`component.port`) that nothing is drawn over; null if none. */
async function exposedPointOf(page: Page, a: string, b: string): Promise<{ x: number; y: number } | null> {
    return page.evaluate(([from, to]) => {
        const { canvas } = (window as unknown as { __tlmhub: { canvas: { clientFromScene(p: { x: number; y: number }): { x: number; y: number } } } }).__tlmhub;
        const line = document.querySelector(`.canvas .connection[data-from="${from}"][data-to="${to}"], .canvas .connection[data-from="${to}"][data-to="${from}"]`);
        if (!line) return null;
        const points = line.getAttribute('points')!.split(' ').map((p) => p.split(',').map(Number));
        for (const t of [0.5, 0.3, 0.7, 0.15, 0.85]) {
            for (let i = 0; i + 1 < points.length; i++) {
                const at = canvas.clientFromScene({ x: points[i][0] + t * (points[i + 1][0] - points[i][0]), y: points[i][1] + t * (points[i + 1][1] - points[i][1]) });
                const hit = document.elementFromPoint(at.x, at.y)?.closest('.connection, .line-hit');
                const ends = [hit?.getAttribute('data-from'), hit?.getAttribute('data-to')];
                if ((ends[0] === from && ends[1] === to) || (ends[0] === to && ends[1] === from)) return at;
            }
        }
        return null;
    }, [a, b]);
}

/**
 * Deletes a drawn line from its own context menu, opened where the line shows; a line hidden
 * under its ends' markers is first pulled clear by moving the other end's component down.
 */
async function deleteLine(page: Page, mine: string, other: string): Promise<void> {
    const line = page.locator(`.canvas .connection[data-from="${mine}"][data-to="${other}"], .canvas .connection[data-from="${other}"][data-to="${mine}"]`);
    let at = await exposedPointOf(page, mine, other);
    if (!at) {
        const body = (await page.locator(`.canvas .component[data-name="${other.slice(0, other.lastIndexOf('.'))}"] .icon-frame`).boundingBox())!;
        await page.mouse.move(body.x + body.width / 2, body.y + body.height / 2);
        await page.mouse.down();
        await page.mouse.move(body.x + body.width / 2 + 10, body.y + body.height / 2 + 60, { steps: 6 });
        await page.mouse.up();
        at = await exposedPointOf(page, mine, other);
    }
    expect(at, `a part of the line ${mine} – ${other} to press`).not.toBeNull();
    await page.mouse.click(at!.x, at!.y, { button: 'right' });
    await page.locator('.context-menu [data-entry="delete"]').click();
    await expect(line).toHaveCount(0);
}

test('every power port of the servo valve and the relief valve is connected by a drag from its marker, never a parameter port', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    let connected = 0;
    for (const [component, portName] of POWER_PORTS) {
        const lines = await linesOn(page, component, portName);
        expect(lines.length, `${component}.${portName} is connected in the example`).toBeGreaterThan(0);
        for (const [mine, other] of lines) {
            await deleteLine(page, mine, other);
            const [otherComponent, otherPort] = [other.slice(0, other.lastIndexOf('.')), other.slice(other.lastIndexOf('.') + 1)];
            await dragPortToPort(page, [component, portName], [otherComponent, otherPort]);
            // the same two ports again: the drag took the power port under the pointer at both ends
            await expect.poll(() => linesOn(page, component, portName)).toContainEqual([mine, other]);
            connected++;
        }
    }
    expect(connected).toBeGreaterThanOrEqual(POWER_PORTS.length);
    // no parameter port was shown or connected on the way
    await expect(port(page, VALVE, 'x_pb')).toBeHidden();
    await expect(port(page, RELIEF, 'tao')).toBeHidden();
    for (const [component, portName] of [[VALVE, 'x_pb'], [RELIEF, 'tao'], [RELIEF, 'p_max']]) {
        expect(await linesOn(page, component, portName), `${component}.${portName}`).toEqual([]);
    }
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
