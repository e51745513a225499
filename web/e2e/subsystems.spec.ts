// Subsystems as a Hopsan user works with them: grouping places the system ports apart, deleting
// a subsystem is undone like any edit, and the browser's Back and Forward move through the levels.
import { test, expect, type Page } from './fixtures';
import { login, openExample } from './helpers';

async function select(page: Page, names: string[]): Promise<void> {
    await page.locator(`.canvas .component[data-name="${names[0]}"] .icon-frame`).click();
    for (const name of names.slice(1)) {
        await page.locator(`.canvas .component[data-name="${name}"] .icon-frame`).click({ modifiers: ['Shift'] });
    }
}

test('grouping places the system ports apart; deleting the subsystem is undone', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    await select(page, ['4_3_Servo_Valve', 'Pressure_Relief_Valve']);
    await page.getByTestId('group').click();
    const sub = page.locator('.canvas .component.subsystem[data-name="Subsystem"]');
    await expect(sub).toBeVisible();
    // the note comes when the grouping (ports placed included) is done
    await expect(page.getByText('Grouped 2 components into Subsystem')).toBeVisible();
    // apart on the box as well as inside it
    const boxPorts = page.locator('.canvas [data-component="Subsystem"][data-port]');
    expect(await boxPorts.count()).toBeGreaterThanOrEqual(2);
    const closest = () => boxPorts.evaluateAll((els) => {
        const centres = els.map((el) => {
            const r = el.getBoundingClientRect();
            return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
        });
        return Math.min(...centres.flatMap((a, i) => centres.slice(i + 1).map((b) => Math.hypot(a.x - b.x, a.y - b.y))));
    });
    await expect.poll(closest).toBeGreaterThan(4);

    await sub.locator('.icon-frame').dblclick();
    await expect(page.locator('.breadcrumb')).toContainText('Subsystem');
    const ports = page.locator('.canvas .component.system-port');
    expect(await ports.count()).toBeGreaterThanOrEqual(2);
    const centres = await ports.evaluateAll((els) => els.map((el) => {
        const r = el.getBoundingClientRect();
        return { x: r.x + r.width / 2, y: r.y + r.height / 2, size: r.width };
    }));
    for (const [i, a] of centres.entries()) {
        for (const b of centres.slice(i + 1)) expect(Math.hypot(a.x - b.x, a.y - b.y)).toBeGreaterThan(a.size);
    }

    await page.goBack();
    await expect(page.locator('.breadcrumb .crumb')).toHaveCount(1);
    await sub.locator('.icon-frame').click();
    await page.keyboard.press('Delete');
    await expect(sub).toHaveCount(0);
    await page.keyboard.press('Control+z');
    await expect(sub).toBeVisible();
    await sub.locator('.icon-frame').dblclick();
    await expect(page.locator('.canvas .component[data-name="4_3_Servo_Valve"]')).toBeVisible();
    await expect(page.locator('.canvas .component[data-name="Pressure_Relief_Valve"]')).toBeVisible();
});

test('browser Back leaves a subsystem for the level above, still in the editor', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'F16systemManeuver');
    const top = page.url();
    await page.locator('.canvas .component[data-name="Subsystem"] .icon-frame').dblclick();
    await expect(page.locator('.canvas .component[data-name="Gearbox_driven_pump_A"]')).toBeVisible();
    expect(page.url()).toMatch(/[?&]path=Subsystem$/);

    // a reload opens the same level
    await page.reload();
    await expect(page.locator('.canvas .component[data-name="Gearbox_driven_pump_A"]')).toBeVisible();

    await page.goBack();
    await expect(page.getByTestId('model-name')).toHaveText('F16systemManeuver');
    await expect(page.locator('.canvas .component[data-name="Subsystem"]')).toBeVisible();
    await expect(page.locator('.breadcrumb .crumb')).toHaveCount(1);
    expect(page.url()).toBe(top);

    await page.goForward();
    await expect(page.locator('.canvas .component[data-name="Gearbox_driven_pump_A"]')).toBeVisible();
});
