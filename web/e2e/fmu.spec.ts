// Issue 20.4: "Download FMU" for the open model shows the FMU's interface and downloads the file.
import { mkdirSync, copyFileSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect } from './fixtures';
import { baseUrl, login, tokenOf } from './helpers';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));
// u -> gain -> y, and a hydraulic line between two C-type power ports
const fmuGain = fileURLToPath(new URL('../../tests/server/data/FmuGain.hmf', import.meta.url));

test('the FMU dialog lists the interface and downloads an FMU with its model description', async ({ page, request }) => {
    await login(page, 'alice');
    const uploaded = await request.post(`${baseUrl()}/api/v1/models?name=FmuGain`, {
        headers: { Authorization: `Bearer ${await tokenOf(page)}`, 'Content-Type': 'application/xml' },
        data: readFileSync(fmuGain, 'utf8'),
    });
    expect(uploaded.status()).toBe(201);
    const { id } = await uploaded.json() as { id: number };
    await page.goto(`${baseUrl()}/#/model/${id}`);
    await expect(page.getByTestId('model-name')).toHaveText('FmuGain');

    await page.getByTestId('download-fmu').click();
    const dialog = page.getByTestId('fmu-dialog');
    await expect(dialog.getByTestId('fmu-file')).toHaveText('FmuGain.fmu');
    await expect(dialog.getByTestId('fmu-inputs').locator('.fmu-name')).toHaveText(['u']);
    await expect(dialog.getByTestId('fmu-outputs').locator('.fmu-name')).toHaveText(['y']);
    await expect(dialog.getByTestId('fmu-power-ports').locator('tr.fmu-port')).toHaveCount(2);
    await expect(dialog.getByTestId('fmu-power-ports').locator('.fmu-name').first()).toHaveText('PA.c');
    await expect(dialog.getByTestId('fmu-step')).toHaveText('0.001 s');
    await expect(dialog.getByTestId('fmu-hint')).toHaveCount(0);

    // A component parameter offered as an FMU parameter.
    await dialog.getByTestId('fmu-parameters-input').fill('Gain.k');
    await dialog.getByTestId('fmu-refresh').click();
    await expect(dialog.getByTestId('fmu-parameters').locator('.fmu-name')).toHaveText(['Gain.k']);
    mkdirSync(screenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}fmu-download.png` });
    copyFileSync(`${screenshots}fmu-download.png`, `${docsScreenshots}fmu-download.png`);

    const [fmu] = await Promise.all([page.waitForEvent('download'), dialog.getByTestId('fmu-download').click()]);
    expect(fmu.suggestedFilename()).toBe('FmuGain.fmu');
    const bytes = readFileSync(await fmu.path());
    expect(bytes.subarray(0, 4).toString('binary')).toBe('PK\x03\x04');
    // a zip names its entries in plain text (local headers and central directory)
    expect(bytes.includes('modelDescription.xml')).toBe(true);
    expect(bytes.includes('binaries/linux64/FmuGain.so')).toBe(true);
    expect(bytes.includes('resources/model.hmf')).toBe(true);
});
