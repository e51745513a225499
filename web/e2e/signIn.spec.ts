// Signing in through the university's OpenID provider, as a person does in Chromium (issue 43):
// "Sign in with University" on the login page, the provider's login and consent pages, and
// back in the app signed in to an account of their own. The provider is a real one (npm's
// oidc-provider, tests/peers/oidc-provider) that this spec starts over TLS on loopback, with a
// second tlmhub-server configured for it.
import { type ChildProcess } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync, chmodSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { freePort, makeTestCertificates, started } from './processes';
import { test, expect } from './fixtures';

const webDir = fileURLToPath(new URL('..', import.meta.url));
const peerDir = resolve(webDir, '../tests/peers/oidc-provider');

let dir = '';
let provider: ChildProcess | undefined;
let server: ChildProcess | undefined;
let appUrl = '';

test.beforeAll(async () => {
    if (!existsSync(join(peerDir, 'node_modules/oidc-provider'))) throw new Error('npm ci --prefix tests/peers/oidc-provider');
    dir = mkdtempSync(join(tmpdir(), 'tlmhub-e2e-oidc-'));
    makeTestCertificates(dir);
    const [providerPort, serverPort] = [await freePort(), await freePort()];
    appUrl = `http://127.0.0.1:${serverPort}`;
    writeFileSync(join(dir, 'provider.json'), JSON.stringify({
        port: providerPort, certFile: join(dir, 'cert.pem'), keyFile: join(dir, 'key.pem'),
        clients: [{ client_id: 'tlmhub', client_secret: 'e2e-client-secret', redirect_uris: [`${appUrl}/api/v1/auth/oidc/university/callback`],
            response_types: ['code'], grant_types: ['authorization_code'] }],
        accounts: { jane: { name: 'Jane Doe', preferred_username: 'jane.doe', groups: ['teachers'] } },
    }));
    provider = await started('node', [join(peerDir, 'provider.mjs'), join(dir, 'provider.json')], /^ready$/m);
    writeFileSync(join(dir, 'client-secret'), 'e2e-client-secret\n');
    chmodSync(join(dir, 'client-secret'), 0o600);
    const binary = resolve(webDir, process.env.TLMHUB_SERVER_BIN ?? '../build/bin/tlmhub-server');
    server = await started(binary, ['--listen', `127.0.0.1:${serverPort}`, '--data-dir', join(dir, 'data'),
        '--web-root', join(webDir, 'dist'), '--password-hash-cost', 'minimal', '--public-url', appUrl,
        '--oidc-issuer', `https://127.0.0.1:${providerPort}`, '--oidc-client-id', 'tlmhub',
        '--oidc-client-secret-file', join(dir, 'client-secret'), '--oidc-name', 'University',
        '--oidc-role', 'teacher=teachers', '--oidc-ca-file', join(dir, 'ca.pem')],
    /listening on http/, { ...process.env, TLMHUB_ADMIN_PASSWORD: 'e2e-admin-password' });
});

test.afterAll(async () => {
    for (const child of [server, provider]) child?.kill('SIGTERM');
    await new Promise((r) => setTimeout(r, 500));
    if (dir) rmSync(dir, { recursive: true, force: true });
});

test('signs in with the university: its login and consent pages, then the app as her own teacher account', async ({ browser }) => {
    // The browser trusts the provider's test certificate as a person's browser trusts the real one.
    const context = await browser.newContext({ ignoreHTTPSErrors: true });
    const page = await context.newPage();
    await page.goto(`${appUrl}/#/login`);
    const button = page.getByRole('link', { name: 'Sign in with University' });
    await expect(button).toBeVisible();
    await page.screenshot({ path: resolve(webDir, '../docs/screenshots/sign-in-providers.png') });
    await button.click();

    await page.locator('input[name="login"]').fill('jane');
    await page.locator('input[name="password"]').fill('whatever-the-university-checks');
    await page.locator('button[type="submit"]').click();
    await page.locator('button[type="submit"]').click();   // consent

    await expect(page).toHaveURL(`${appUrl}/#/models`);
    const token = await page.evaluate(() => sessionStorage.getItem('tlmhub.token'));
    expect(token).toBeTruthy();
    const me = await (await fetch(`${appUrl}/api/v1/auth/me`, { headers: { Authorization: `Bearer ${token}` } })).json();
    expect(me).toMatchObject({ username: 'jane.doe', role: 'teacher' });
    // The one-time key is not left in the address.
    expect(page.url()).not.toContain('signed-in');

    // A sign-in the provider refuses comes back with the reason on the login page.
    await page.goto(`${appUrl}/api/v1/auth/oidc/university/callback?error=access_denied&state=made-up`);
    await expect(page.getByRole('alert')).toContainText('did not succeed');
    await context.close();
});
