// Issue 13.1: a plot window whose legend wraps keeps its size (it used to grow without limit,
// the legend's height feeding back into the plot's through the resize observer).
import { test, expect, type Page } from './fixtures';
import { login, openExample, runAndWait } from './helpers';

interface Heights { page: number; runArea: number; plotWindow: number; canvas: number }

async function heights(page: Page): Promise<Heights> {
    return page.evaluate(() => {
        const box = (sel: string) => (document.querySelector(sel) as HTMLElement).getBoundingClientRect().height;
        return {
            page: document.documentElement.scrollHeight,
            runArea: (document.querySelector('.run-area') as HTMLElement).scrollHeight,
            plotWindow: box('.plot-window'),
            canvas: box('.plot-window canvas'),
        };
    });
}

test('a default run of Position Servo keeps the page and plot heights fixed, also while hovering', async ({ page }) => {
    await login(page, 'alice');
    await openExample(page, 'Position Servo');
    await runAndWait(page);
    const plot = page.locator('.plot-window').first();
    // the scopes' four signals are plotted and their legend wraps onto more than one row
    await expect(plot.locator('.u-legend .u-series:not(:first-child)')).toHaveCount(4);
    const rowTops = await plot.locator('.u-legend .u-series').evaluateAll((rows) => new Set(rows.map((r) => Math.round(r.getBoundingClientRect().top))).size);
    expect(rowTops, 'legend rows').toBeGreaterThan(1);

    const before = await heights(page);
    expect(before.canvas).toBeGreaterThan(100);
    await page.waitForTimeout(2000);
    expect(await heights(page)).toEqual(before);

    // hovering shows values in the legend (wider entries): still no growth
    const canvasBox = (await plot.locator('canvas').boundingBox())!;
    await page.mouse.move(canvasBox.x + canvasBox.width * 0.5, canvasBox.y + canvasBox.height * 0.5);
    await page.mouse.move(canvasBox.x + canvasBox.width * 0.6, canvasBox.y + canvasBox.height * 0.4, { steps: 5 });
    const hovering = await heights(page);
    expect(hovering).toEqual(before);
    await page.waitForTimeout(2000);
    expect(await heights(page)).toEqual(before);
});
