// An LTI 1.3 launch from a course page, as Moodle ("Embed") and Canvas show tlmhub: the test LTI
// platform (tests/peers/lti-platform, npm's jose) runs over TLS on loopback with its own CA, and
// its course page (/course) frames the tool's login initiation URL. Inside that frame the tool's
// login sets its SameSite=None cookie, sends the browser to the platform's /auth, whose page
// posts the ID token back across sites to the tool's launch address, and the browser app opens
// the course's class signed in. The launch page (/api/v1/lti/app) may be framed by registered
// platforms only: a site that is not registered gets Chromium's refusal (frame-ancestors).
import { execFileSync, type ChildProcess } from 'node:child_process';
import { chmodSync, existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import https from 'node:https';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { freePort, makeTestCertificates, started } from './processes';
import { test, expect, type Browser, type Page } from './fixtures';

const webDir = fileURLToPath(new URL('..', import.meta.url));
const peerDir = resolve(webDir, '../tests/peers/lti-platform');
const ADMIN_PASSWORD = 'e2e-admin-password';
const COURSE = { id: 'hyd-101', title: 'Hydraulics 101' };

test.describe.configure({ mode: 'serial' });   // the student's launch needs the class the teacher's made

const logs: string[] = [];   // the server's and the platform's output once started
let dir = '';
let platform: ChildProcess | undefined;
let server: ChildProcess | undefined;
let stranger: https.Server | undefined;
let appUrl = '';
let issuer = '';
let strangerUrl = '';

// What the browser said while a test ran, to tell a browser's refusal from a test's mistake.
function watch(page: Page): string[] {
    const seen: string[] = [];
    page.on('console', (m) => seen.push(`console ${m.type()} [${m.location().url}]: ${m.text()}`));
    page.on('requestfailed', (r) => seen.push(`failed ${r.method()} ${r.url()}: ${r.failure()?.errorText}`));
    page.on('pageerror', (e) => seen.push(`page error: ${e.message}`));
    page.on('response', (r) => {
        if (r.url().includes('/api/v1/lti/') || r.url().startsWith(issuer))
            seen.push(`${r.status()} ${r.request().method()} ${r.url().replace(/id_token=[^&]+/, 'id_token=…')}`);
    });
    return seen;
}

/** Stages a launch at the platform and opens its course page, which frames the tool's login. */
async function openCourse(browser: Browser, user: object): Promise<{ page: Page; seen: string[] }> {
    const staged = await fetchPlatform('/control/launch', { user, context: COURSE });
    const context = await browser.newContext({ ignoreHTTPSErrors: true });   // trusts the test CA as a person's browser trusts a real one
    const page = await context.newPage();
    const seen = watch(page);
    const launched = page.waitForResponse(`${appUrl}/api/v1/lti/launch`);
    await page.goto(`${issuer}/course?launch=${encodeURIComponent(staged.loginUrl)}`);
    await expect(page.getByRole('heading', { name: COURSE.title, level: 1 })).toBeVisible();
    // the launch's form post, in the frame, is taken: 303 to the app (a refusal is 400, its code in the server's log)
    const status = (await launched).status();
    await page.waitForTimeout(status === 303 ? 0 : 500);
    expect(status, `the launch in the frame:\n${seen.join('\n')}\n${logs.join('\n')}`).toBe(303);
    return { page, seen };
}

// A POST to the platform's control API, over its TLS, trusting the test CA.
function fetchPlatform(path: string, body: object): Promise<{ loginUrl: string }> {
    return new Promise((done, fail) => {
        const request = https.request(`${issuer}${path}`, { method: 'POST', ca: readFileSync(join(dir, 'ca.pem')),
            headers: { 'Content-Type': 'application/json' } }, (response) => {
            let text = '';
            response.on('data', (c) => { text += c; });
            response.on('end', () => response.statusCode === 200 ? done(JSON.parse(text)) : fail(new Error(`${path}: ${response.statusCode} ${text}`)));
        });
        request.on('error', fail);
        request.end(JSON.stringify(body));
    });
}

function appFrame(page: Page) {
    const frame = page.frames().find((f) => f !== page.mainFrame());
    if (!frame) throw new Error('the course page has no frame');
    return frame;
}

test.beforeAll(async () => {
    if (!existsSync(join(peerDir, 'node_modules/jose'))) throw new Error('npm ci --prefix tests/peers/lti-platform');
    dir = mkdtempSync(join(tmpdir(), 'tlmhub-e2e-lti-launch-'));
    makeTestCertificates(dir);
    const openssl = (...args: string[]) => execFileSync('openssl', args, { cwd: dir, stdio: 'ignore' });
    openssl('genpkey', '-algorithm', 'RSA', '-pkeyopt', 'rsa_keygen_bits:2048', '-out', 'tool-key.pem');
    chmodSync(join(dir, 'tool-key.pem'), 0o600);

    const [platformPort, serverPort, strangerPort] = [await freePort(), await freePort(), await freePort()];
    appUrl = `http://127.0.0.1:${serverPort}`;
    issuer = `https://127.0.0.1:${platformPort}`;
    writeFileSync(join(dir, 'platform.json'), JSON.stringify({
        port: platformPort, certFile: join(dir, 'cert.pem'), keyFile: join(dir, 'key.pem'),
        clientId: 'tlmhub-tool', deploymentId: 'deployment-1',
        tool: { loginUrl: `${appUrl}/api/v1/lti/login`, launchUrl: `${appUrl}/api/v1/lti/launch`, jwksUrl: `${appUrl}/api/v1/lti/jwks` },
    }));
    platform = await started('node', [join(peerDir, 'platform.mjs'), join(dir, 'platform.json')], /^ready$/m);

    const binary = resolve(webDir, process.env.TLMHUB_SERVER_BIN ?? '../build/bin/tlmhub-server');
    server = await started(binary, ['--listen', `127.0.0.1:${serverPort}`, '--data-dir', join(dir, 'data'),
        '--web-root', join(webDir, 'dist'), '--password-hash-cost', 'minimal', '--public-url', appUrl,
        '--lti-key-file', join(dir, 'tool-key.pem'), '--lti-ca-file', join(dir, 'ca.pem')],
    /listening on http/, { ...process.env, TLMHUB_ADMIN_PASSWORD: ADMIN_PASSWORD });

    const login = await fetch(`${appUrl}/api/v1/auth/login`, { method: 'POST', headers: { 'Content-Type': 'application/json' },
        body: JSON.stringify({ username: 'admin', password: ADMIN_PASSWORD }) });
    expect(login.status, 'admin login').toBe(200);
    const { token } = await login.json() as { token: string };
    const registered = await fetch(`${appUrl}/api/v1/admin/lti/platforms`, { method: 'POST',
        headers: { 'Content-Type': 'application/json', Authorization: `Bearer ${token}` },
        body: JSON.stringify({ name: 'Test platform', issuer, client_id: 'tlmhub-tool', auth_url: `${issuer}/auth`,
            token_url: `${issuer}/token`, jwks_url: `${issuer}/jwks`, deployment_ids: ['deployment-1'] }) });
    expect(registered.status, `register the platform: ${await registered.clone().text()}`).toBe(201);

    // A site that is not registered: the same certificate and host as the platform, another port
    // (so another origin), with a page that frames the launch page.
    stranger = https.createServer({ cert: readFileSync(join(dir, 'cert.pem')), key: readFileSync(join(dir, 'key.pem')) }, (_req, res) => {
        res.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8' });
        res.end(`<!DOCTYPE html><html><head><meta charset="utf-8"><title>Elsewhere</title></head>
<body><h1>Not a registered platform</h1><iframe src="${appUrl}/api/v1/lti/app" width="100%" height="500"></iframe></body></html>`);
    });
    await new Promise<void>((done) => stranger!.listen(strangerPort, '127.0.0.1', done));
    strangerUrl = `https://127.0.0.1:${strangerPort}`;
});

test.afterAll(async () => {
    for (const child of [server, platform]) child?.kill('SIGTERM');
    stranger?.close();
    await new Promise((r) => setTimeout(r, 500));
    if (dir) rmSync(dir, { recursive: true, force: true });
});

test("a teacher's launch inside the platform's course page opens the course's class, signed in", async ({ browser }) => {
    const { page, seen } = await openCourse(browser, { sub: 't-1', name: 'Grace Hopper', roles: ['Instructor'] });
    const frame = page.frameLocator('iframe');
    await expect(frame.getByTestId('class-name'), seen.join('\n')).toHaveText(COURSE.title);
    await expect(frame.getByTestId('class-page')).toContainText('teacher Grace_Hopper · you: teacher');
    await expect(frame.getByTestId('user')).toHaveText('Grace_Hopper (user)');
    await expect(frame.getByTestId('members')).toContainText('Grace_Hopper');
    await expect(frame.getByTestId('gradebook')).toBeVisible();

    // the one-time key is not left in the frame's address
    const app = appFrame(page);
    expect(app.url()).toMatch(new RegExp(`^${appUrl}/api/v1/lti/app#/class/\\d+$`));
    expect(app.url()).not.toContain('signed-in');
    const token = await app.evaluate(() => sessionStorage.getItem('tlmhub.token'));
    const me = await (await fetch(`${appUrl}/api/v1/auth/me`, { headers: { Authorization: `Bearer ${token}` } })).json();
    expect(me).toMatchObject({ username: 'Grace_Hopper', role: 'user' });

    await expect(page.locator('#toasts .toast')).toHaveCount(0);
    await page.screenshot({ path: resolve(webDir, '../docs/screenshots/lti-launch.png'), fullPage: true });
    await page.context().close();
});

test("a student's launch into the same course lands on the same class as a student", async ({ browser }) => {
    const { page, seen } = await openCourse(browser, { sub: 's-1', name: 'Ada Lovelace', roles: ['Learner'] });
    const frame = page.frameLocator('iframe');
    await expect(frame.getByTestId('class-name'), seen.join('\n')).toHaveText(COURSE.title);
    await expect(frame.getByTestId('class-page')).toContainText('teacher Grace_Hopper · you: student');
    await expect(frame.getByTestId('user')).toHaveText('Ada_Lovelace (user)');
    await expect(frame.getByTestId('assignments')).toContainText('No open assignments yet.');
    // no staff controls and no members list
    await expect(frame.getByTestId('members')).toHaveCount(0);
    await expect(frame.getByTestId('gradebook')).toHaveCount(0);
    await expect(frame.getByTestId('join-code')).toHaveCount(0);
    await expect(frame.getByTestId('export-gradebook')).toHaveCount(0);
    await expect(frame.getByTestId('new-assignment')).toHaveCount(0);
    expect(appFrame(page).url()).not.toContain('signed-in');
    await page.context().close();
});

test('a site that is not a registered platform cannot frame the launch page', async ({ browser, contentSecurityPolicyViolations }) => {
    const context = await browser.newContext({ ignoreHTTPSErrors: true });
    const page = await context.newPage();
    const seen = watch(page);
    const launchPage = page.waitForResponse(`${appUrl}/api/v1/lti/app`);
    await page.goto(strangerUrl);
    // the server answers the page, with the registered platform as the only other ancestor …
    const answered = await launchPage;
    expect(answered.status()).toBe(200);
    expect(await answered.headerValue('content-security-policy')).toContain(`frame-ancestors 'self' ${issuer}`);
    // … and Chromium refuses to show it here: the frame holds its error page, not the app
    await expect.poll(() => appFrame(page).url(), { message: seen.join('\n') }).toMatch(/^chrome-error:/);
    await expect(page.frameLocator('iframe').locator('#app, main, [data-testid]')).toHaveCount(0);
    // and says why (the fixture's watch for violations is told this one is expected)
    const refusal = `Framing '${appUrl}/' violates the following Content Security Policy directive: "frame-ancestors 'self' ${issuer}". The request has been blocked.`;
    await expect.poll(() => contentSecurityPolicyViolations.map((v) => v.slice(v.indexOf(': ') + 2).trim())).toEqual([refusal]);
    contentSecurityPolicyViolations.length = 0;
    await context.close();
});

