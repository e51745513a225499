// Issue 39.4: the aero, vehicle and controller examples drawn with symbols of their own, no
// labelled boxes (the upright rule for turned icons is proven in iconOrientation.test.ts).
import { fileURLToPath } from 'node:url';
import { test, expect, type Page } from './fixtures';
import { baseUrl, login, openExample } from './helpers';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

// a large window: the whole model fits with its icons big enough to tell apart
test.use({ viewport: { width: 1900, height: 1250 } });

/**
 * Opens an example from the start page and checks every body has its symbol, then keeps a
 * picture of the canvas, zoomed in on one component (`zoomOn`) by a wheel step when the model is large.
 */
async function openAndShoot(page: Page, example: string, types: string[], file: string, zoomOn?: string): Promise<void> {
    await page.goto(`${baseUrl()}/#/`);
    await openExample(page, example);
    for (const type of types) await expect(page.locator(`.canvas .component[data-type="${type}"] .icon[data-family]`).first(), type).toBeVisible();
    await expect(page.locator('.canvas .icon-fallback')).toHaveCount(0);
    if (zoomOn) {
        const box = (await page.locator(`.canvas .component[data-name="${zoomOn}"] .icon-frame`).boundingBox())!;
        await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
        await page.mouse.wheel(0, -240);
        await expect(page.locator(`.canvas .component[data-name="${zoomOn}"]`)).toBeVisible();
    }
    await page.getByTestId('canvas').screenshot({ path: `${docsScreenshots}${file}` });
}

test('F16 and ElectricVehicle: every component drawn as its symbol, none as a labelled box', async ({ page }) => {
    await login(page, 'alice');
    await openAndShoot(page, 'F16InterceptMission',
        ['AeroAircraft6DOFSS', 'AeroJetEngine', 'AeroFuelTank', 'AeroAtmosphere', 'SignalPID', 'SignalPIlead', 'SignalAttitudeControl', 'SignalEarthCoordinates', 'SignalStopSimulation'],
        'f16-icons.png', 'AeroAircraft6DOFSS');
    await openAndShoot(page, 'ElectricVehicle', ['MechanicVehicle1D', 'ElectricIcontroller', 'ElectricBattery', 'ElectricMotorGear'], 'electric-vehicle-icons.png');
});
