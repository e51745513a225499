// Grouping and ungrouping on the server: a group runs exactly as the components did, the
// refusal of a group that could not run is shown, and ungroup gives the model back.
import { test, expect, type Page, type APIRequestContext } from './fixtures';
import { api, login, openExample, runAndWait } from './helpers';
import type { ResultsJson } from '../src/protocol/types';

const SERVO = 'Position Servo';

async function results(request: APIRequestContext, page: Page, job: number): Promise<Map<string, number[]>> {
    const table = await api<ResultsJson>(request, page, `/jobs/${job}/results?format=json`);
    return new Map(table.variables.map((v) => [v.name, v.data]));
}

async function select(page: Page, names: string[]): Promise<void> {
    await page.locator(`.canvas .component[data-name="${names[0]}"] .icon-frame`).click();
    for (const name of names.slice(1)) {
        await page.locator(`.canvas .component[data-name="${name}"] .icon-frame`).click({ modifiers: ['Shift'] });
    }
}

test('groups components into a subsystem and ungroups it with the same results', async ({ page, request }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    const before = await results(request, page, await runAndWait(page));
    expect(before.size).toBeGreaterThan(50);   // every logged variable, not a selection

    const grouped = ['4_3_Servo_Valve', 'Pressure_Relief_Valve', 'Q_type_Fixed_Displacement_Pump_1'];
    await select(page, grouped);
    await page.getByTestId('group').click();
    const sub = page.locator('.canvas .component.subsystem[data-name="Subsystem"]');
    await expect(sub).toBeVisible();
    await expect(page.locator('.canvas .component[data-name="4_3_Servo_Valve"]')).toHaveCount(0);
    // an edit like any other: not saved, and undoable
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'true');
    await expect(page.getByTestId('undo')).toBeEnabled();

    const inGroup = await results(request, page, await runAndWait(page));
    for (const [name, data] of before) {
        const moved = grouped.includes(name.split('#')[0]) ? `Subsystem$${name}` : name;
        expect(inGroup.get(moved), moved).toEqual(data);
    }

    await sub.locator('.icon-frame').click();
    await page.getByTestId('ungroup').click();
    await expect(sub).toHaveCount(0);
    await expect(page.locator('.canvas .component[data-name="4_3_Servo_Valve"]')).toBeVisible();
    const after = await results(request, page, await runAndWait(page));
    expect([...after.keys()]).toEqual([...before.keys()]);
    for (const [name, data] of before) expect(after.get(name), name).toEqual(data);

    // undo of the ungroup groups again
    await page.getByTestId('undo').click();
    await expect(sub).toBeVisible();
});

test('a group that could not run is refused with the reason', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, SERVO);
    await select(page, ['Mass', 'Cylinder_C']);
    await page.getByTestId('group').click();
    await expect(page.getByTestId('editor-messages').getByRole('alert')).toContainText('undefined C/Q/S kind');
    await expect(page.locator('.canvas .component[data-name="Mass"]')).toBeVisible();
    await expect(page.locator('.canvas .component.subsystem')).toHaveCount(0);
});
