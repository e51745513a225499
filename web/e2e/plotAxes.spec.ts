// Issue 13.4: one y axis per unit with SI-prefixed ticks, at most three per window; curves
// named after the port clicked; the cursor moves in every plot window at once.
import { test, expect } from './fixtures';
import { login, openExample, plotVariable, runAndWait } from './helpers';

test('plots of pressure, position and flow get one axis each (MPa, mm); a fourth unit opens a new window', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const pressure = await plotVariable(page, 'Cylinder_C', 'P1', 'Pressure');
    await plotVariable(page, 'Mass', 'P2', 'Position');
    await plotVariable(page, 'Cylinder_C', 'P1', 'Flow');
    await runAndWait(page);
    const first = page.locator('.plot-window').first();
    await expect(first).toHaveAttribute('data-axes', /^[kM]?Pa,mm,m\^3\/s$/);
    await expect(first.locator('.chip').first()).toHaveText(/^Cylinder_C\.P1 Pressure/);
    expect(pressure).toMatch(/#Pressure$/);

    await plotVariable(page, 'Mass', 'P2', 'Velocity');
    await expect(page.locator('.plot-window:not(.analysis-window)')).toHaveCount(2);
    const second = page.locator('.plot-window').nth(1);
    await expect(second.locator('.chip')).toHaveText([/Mass\.P2 Velocity/]);
    await expect(second.locator('canvas').first()).toBeVisible();

    await first.screenshot({ path: 'e2e/screenshots/plot-axes.png' });
    // the cursor over one window shows the same time in the other's legend
    const box = (await first.locator('.u-over').boundingBox())!;
    await page.mouse.move(box.x + box.width * 0.4, box.y + box.height / 2);
    const timeIn = async (w: typeof first) => w.locator('.u-legend .u-series').first().locator('.u-value').textContent();
    await expect.poll(() => timeIn(second)).not.toBe('--');
    expect(await timeIn(second)).toBe(await timeIn(first));
});
