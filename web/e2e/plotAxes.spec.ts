// Issue 13.4: one y axis per unit with SI-prefixed ticks; curves named after the port clicked;
// the cursor moves in every plot window at once. Issue 38.5: a fourth unit gets an axis of its
// own; a fifth asks whether to add an axis or open a window, which then opens in sight.
import { test, expect } from './fixtures';
import { login, openExample, plotVariable, runAndWait } from './helpers';

test('pressure, position, flow and velocity get one axis each (MPa, mm); a fifth unit opens a new window when chosen', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const pressure = await plotVariable(page, 'Cylinder_C', 'P1', 'Pressure');
    await plotVariable(page, 'Mass', 'P2', 'Position');
    await plotVariable(page, 'Cylinder_C', 'P1', 'Flow');
    await plotVariable(page, 'Mass', 'P2', 'Velocity');
    await runAndWait(page);
    const first = page.locator('.plot-window').first();
    await expect(page.locator('.plot-window:not(.analysis-window)')).toHaveCount(1);
    await expect(first).toHaveAttribute('data-axes', /^[kM]?Pa,mm,m\^3\/s,m?m\/s$/);
    await expect(first.locator('.chip').first()).toHaveText(/^Cylinder_C\.P1 Pressure/);
    expect(pressure).toMatch(/#Pressure$/);

    // a fifth unit: the user is asked, and the new window is where it can be seen
    await plotVariable(page, 'Mass', 'P2', 'Force');
    const choice = page.getByTestId('axis-choice');
    await expect(choice).toBeInViewport();
    await choice.getByRole('button', { name: 'Open a new plot window' }).click();
    await expect(page.locator('.plot-window:not(.analysis-window)')).toHaveCount(2);
    const second = page.locator('.plot-window').nth(1);
    await expect(second.locator('.chip')).toHaveText([/Mass\.P2 Force/]);
    await expect(second).toHaveClass(/active/);
    await expect(second).toBeInViewport();
    await expect(second.locator('canvas').first()).toBeVisible();

    await first.screenshot({ path: 'e2e/screenshots/plot-axes.png' });
    // the cursor over one window shows the same time in the other's legend
    const box = (await first.locator('.u-over').boundingBox())!;
    await page.mouse.move(box.x + box.width * 0.4, box.y + box.height / 2);
    const timeIn = async (w: typeof first) => w.locator('.u-legend .u-series').first().locator('.u-value').textContent();
    // ('-- s' off the plot)
    await expect.poll(async () => (await timeIn(second)) ?? '--').not.toMatch(/^--/);
    expect(await timeIn(second)).toBe(await timeIn(first));
});
