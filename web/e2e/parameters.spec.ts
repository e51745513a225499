// Issue 13.7: the parameters panel reads in words (descriptions, short names, units), node
// start values in their own section, long names wrapped inside the panel.
import { test, expect } from './fixtures';
import { login, openExample } from './helpers';

test('parameters show descriptions, short names and units; start values apart; no overflow', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    await page.locator('.canvas .component[data-name="Translational_Spring"] .icon-frame').click();
    const panel = page.getByLabel('Parameters');
    const spring = panel.locator('tr[data-param="k#Value"]');
    await expect(spring.locator('th .param-name')).toHaveText('k');
    await expect(spring.locator('th .param-label')).not.toHaveText(/#/);
    await expect(spring.locator('td.unit')).toHaveText('N/m');
    await expect(panel.locator('.param-table th', { hasText: '#Value' })).toHaveCount(0);

    await page.locator('.canvas .component[data-name="Tank_C"] .icon-frame').click();
    const startValues = panel.getByTestId('start-values');
    await expect(startValues.locator('tr[data-param="P1#HeatFlow"] th')).toContainText('P1: Heat flow');
    await expect(panel.locator('.param-table').first().locator('tr[data-param="P1#HeatFlow"]')).toHaveCount(0);
    await panel.screenshot({ path: 'e2e/screenshots/parameters.png' });
    // nothing sticks out of the panel sideways
    const overflow = await panel.evaluate((el) => el.scrollWidth - el.clientWidth);
    expect(overflow).toBeLessThanOrEqual(0);
});
