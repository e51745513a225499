// Issue 13.6: the palette in Hopsan's library folders, with icons, searchable by display name.
import { mkdirSync, copyFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect } from './fixtures';
import { login, openExample } from './helpers';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

test('the palette shows library folders with icons; "scope" finds the scope', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    const palette = page.getByLabel('Component palette');
    await expect(palette.locator('.palette-group[data-folder="Hydraulic"] .palette-subfolder-name', { hasText: 'Valves' }).first()).toBeVisible();
    await expect(palette.locator('.palette-item[data-type="Hydraulic43Valve"] svg.palette-icon')).toBeVisible();
    mkdirSync(screenshots, { recursive: true });
    mkdirSync(docsScreenshots, { recursive: true });
    await palette.screenshot({ path: `${screenshots}palette.png` });
    copyFileSync(`${screenshots}palette.png`, `${docsScreenshots}palette.png`);

    await page.getByLabel('Search components').fill('scope');
    const found = palette.locator('.palette-item');
    await expect(found.filter({ hasText: 'Scope' }).first()).toHaveAttribute('data-type', 'SignalSink');
    const scopes = page.locator('.canvas .component:not(.system-port)');
    const before = await scopes.count();
    await found.filter({ hasText: 'Scope' }).first().dblclick();
    await expect(scopes).toHaveCount(before + 1);
});
