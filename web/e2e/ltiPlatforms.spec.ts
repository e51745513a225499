// The administrator's page of learning platforms (LTI 1.3, #/admin/lti): from the account page,
// an administrator registers a Moodle in the form, sees it in the table, edits it, is refused a
// second one with the same issuer and client id, and removes it. A second server, started as
// an LTI tool (--lti-key-file, --public-url), shows the addresses a platform's administrator
// enters; the screenshot docs/screenshots/lti-platforms.png is of that page.
import { execFileSync, type ChildProcess } from 'node:child_process';
import { chmodSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { freePort, started } from './processes';
import { test, expect, type Page } from './fixtures';
import { api, baseUrl } from './helpers';
import { ADMIN_PASSWORD } from './globalSetup';

const webDir = fileURLToPath(new URL('..', import.meta.url));

const MOODLE = {
    Name: 'Moodle of the faculty',
    Issuer: 'https://moodle.uni.edu',
    'Client id': 'f1x4Q2',
    'Authentication URL': 'https://moodle.uni.edu/mod/lti/auth.php',
    'Token URL': 'https://moodle.uni.edu/mod/lti/token.php',
    'Keyset URL': 'https://moodle.uni.edu/mod/lti/certs.php',
    'Deployment ids': '1, 2',
};

async function fillPlatform(page: Page, values: Partial<typeof MOODLE>): Promise<void> {
    const form = page.locator('form.lti-form');
    for (const [label, value] of Object.entries(values)) await form.getByLabel(label, { exact: true }).fill(value);
}

/** Logs in as the administrator at `url` and goes from the account page to the learning platforms. */
async function openPlatformsPage(page: Page, url: string): Promise<void> {
    await page.goto(`${url}/#/login`);
    await page.getByLabel('User name').fill('admin');
    await page.getByLabel('Password').fill(ADMIN_PASSWORD);
    await page.getByRole('button', { name: 'Log in' }).click();
    await expect(page.getByTestId('user')).toHaveText('admin (admin)');
    await page.getByTestId('user').click();
    await page.getByRole('link', { name: 'Learning platforms (LTI)' }).click();
    await expect(page).toHaveURL(/#\/admin\/lti$/);
    await expect(page.getByRole('heading', { name: 'Learning platforms (LTI)', level: 1 })).toBeVisible();
}

test('an administrator registers, edits and removes a learning platform; a second with the same issuer and client id is refused',
    async ({ page, request }) => {
        await openPlatformsPage(page, baseUrl());
        // this server is no LTI tool: launches are off, and the page says what turns them on
        await expect(page.getByTestId('lti-off')).toContainText('--lti-key-file');
        const table = page.getByTestId('lti-platforms');
        await expect(table).toContainText('No platform is registered yet.');

        // the browser checks what the server checks
        await fillPlatform(page, { ...MOODLE, Issuer: 'http://moodle.uni.edu' });
        await page.getByRole('button', { name: 'Register platform' }).click();
        await expect(page.getByText('The issuer must be an https:// address.')).toBeVisible();
        await expect(page.getByLabel('Issuer', { exact: true })).toHaveAttribute('aria-invalid', 'true');

        await fillPlatform(page, { Issuer: MOODLE.Issuer });
        await page.getByRole('button', { name: 'Register platform' }).click();
        const row = table.locator('tbody tr', { hasText: MOODLE.Name });
        await expect(row).toBeVisible();
        await expect(row).toContainText(MOODLE.Issuer);
        await expect(row).toContainText(MOODLE['Client id']);
        await expect(row).toContainText('1, 2');
        await expect(page.getByLabel('Name', { exact: true })).toHaveValue('');

        // edit: the form takes the platform's values; saved, the table shows the change
        await row.getByRole('button', { name: `Edit ${MOODLE.Name}` }).click();
        await expect(page.getByRole('heading', { name: `Edit "${MOODLE.Name}"` })).toBeVisible();
        await expect(page.getByLabel('Token URL', { exact: true })).toHaveValue(MOODLE['Token URL']);
        await fillPlatform(page, { Name: 'Moodle', 'Deployment ids': '1\n2\n3' });
        await page.getByRole('button', { name: 'Save changes' }).click();
        const edited = table.locator('tbody tr', { hasText: 'Moodle' });
        await expect(edited).toContainText('1, 2, 3');
        await expect(table.locator('tbody tr')).toHaveCount(1);
        const stored = await api<{ platforms: { name: string; deployment_ids: string[] }[] }>(request, page, '/admin/lti/platforms');
        expect(stored.platforms).toEqual([expect.objectContaining({ name: 'Moodle', deployment_ids: ['1', '2', '3'] })]);

        // the same issuer and client id again: the server refuses, and the form says why
        await fillPlatform(page, { ...MOODLE, Name: 'Moodle again' });
        await page.getByRole('button', { name: 'Register platform' }).click();
        await expect(page.getByTestId('lti-form-error')).toContainText('issuer and client id');
        await expect(page.getByLabel('Client id', { exact: true })).toHaveAttribute('aria-invalid', 'true');
        await expect(table.locator('tbody tr')).toHaveCount(1);

        // remove, after the confirmation names what goes with it
        let asked = '';
        page.once('dialog', (dialog) => { asked = dialog.message(); void dialog.accept(); });
        await edited.getByRole('button', { name: 'Remove Moodle' }).click();
        await expect(table.locator('tbody tr')).toHaveCount(0);
        expect(asked).toContain('course links, line items and pending scores go with it; the classes stay');
        await expect(table).toContainText('No platform is registered yet.');
    });

// ---- a server that is an LTI tool

test.describe('with launches on', () => {
    const publicUrl = 'https://tlmhub.uni.edu';
    let dir = '';
    let server: ChildProcess | undefined;
    let appUrl = '';

    test.beforeAll(async () => {
        dir = mkdtempSync(join(tmpdir(), 'tlmhub-e2e-lti-'));
        const key = join(dir, 'tool-key.pem');
        execFileSync('openssl', ['genpkey', '-algorithm', 'RSA', '-pkeyopt', 'rsa_keygen_bits:2048', '-out', key], { stdio: 'ignore' });
        chmodSync(key, 0o600);
        const port = await freePort();
        appUrl = `http://127.0.0.1:${port}`;
        const binary = resolve(webDir, process.env.TLMHUB_SERVER_BIN ?? '../build/bin/tlmhub-server');
        // --public-url is the address platforms and browsers reach the tool at; this test's
        // browser comes in by loopback all the same
        server = await started(binary, ['--listen', `127.0.0.1:${port}`, '--data-dir', join(dir, 'data'),
            '--web-root', join(webDir, 'dist'), '--password-hash-cost', 'minimal', '--public-url', publicUrl,
            '--lti-key-file', key],
        /listening on http/, { ...process.env, TLMHUB_ADMIN_PASSWORD: ADMIN_PASSWORD });
    });

    test.afterAll(async () => {
        server?.kill('SIGTERM');
        await new Promise((r) => setTimeout(r, 500));
        if (dir) rmSync(dir, { recursive: true, force: true });
    });

    test("shows the tool's addresses to enter at the platform, by Moodle's names", async ({ page }) => {
        await openPlatformsPage(page, appUrl);
        const tool = page.getByTestId('lti-tool');
        await expect(page.getByTestId('lti-off')).toHaveCount(0);
        const address = (label: string) => tool.locator('tr', { has: page.getByRole('rowheader', { name: label }) }).locator('code');
        await expect(address('Tool URL')).toHaveText(`${publicUrl}/api/v1/lti/launch`);
        await expect(address('Initiate login URL')).toHaveText(`${publicUrl}/api/v1/lti/login`);
        await expect(address('Redirection URI(s)')).toContainText(`${publicUrl}/api/v1/lti/launch`);
        await expect(address('Public keyset URL')).toHaveText(`${publicUrl}/api/v1/lti/jwks`);
        await expect(tool.getByRole('button', { name: 'Copy Tool URL' })).toBeEnabled();

        await fillPlatform(page, MOODLE);
        await page.getByRole('button', { name: 'Register platform' }).click();
        await expect(page.getByTestId('lti-platforms').locator('tbody tr', { hasText: MOODLE.Name })).toBeVisible();
        await expect(page.locator('#toasts .toast')).toHaveCount(0);   // "Registered …" gone
        await page.getByRole('heading', { name: 'Learning platforms (LTI)', level: 1 }).scrollIntoViewIfNeeded();
        await page.screenshot({ path: resolve(webDir, '../docs/screenshots/lti-platforms.png'), fullPage: true });
    });
});
