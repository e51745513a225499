// Starts tlmhub-server for the suite: fresh data directory, free port, the app from web/dist,
// the Hopsan examples read in place; creates the users alice and bob. Returns the teardown.
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const webDir = fileURLToPath(new URL('..', import.meta.url));

export const ADMIN_PASSWORD = 'e2e-admin-password';
export const USERS = { alice: 'alice-password', bob: 'bob-password' };

async function post(url: string, body: unknown, token?: string): Promise<Response> {
    return fetch(url, {
        method: 'POST',
        headers: { 'Content-Type': 'application/json', ...(token ? { Authorization: `Bearer ${token}` } : {}) },
        body: JSON.stringify(body),
    });
}

export default async function globalSetup(): Promise<() => Promise<void>> {
    const binary = resolve(webDir, process.env.TLMHUB_SERVER_BIN ?? '../build/bin/tlmhub-server');
    const examples = resolve(webDir, process.env.TLMHUB_EXAMPLES_DIR ?? '../../shared/hopsan-models/Example Models');
    const webRoot = join(webDir, 'dist');
    for (const [what, path] of [['server binary', binary], ['examples', examples], ['built app (npm run build)', join(webRoot, 'index.html')]]) {
        if (!existsSync(path)) throw new Error(`e2e: ${what} not found at ${path}`);
    }
    const dataDir = mkdtempSync(join(tmpdir(), 'tlmhub-e2e-'));
    // Cheap password hashes: every test logs in (a test server, as tests/server/ServerHarness.cpp's).
    const server = spawn(binary, ['--listen', '127.0.0.1:0', '--data-dir', dataDir, '--web-root', webRoot, '--examples-dir', examples,
        '--password-hash-cost', 'minimal'],
        { env: { ...process.env, TLMHUB_ADMIN_PASSWORD: ADMIN_PASSWORD }, stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    const url = await new Promise<string>((resolveUrl, reject) => {
        const timer = setTimeout(() => reject(new Error(`e2e: server did not report its address:\n${output}`)), 30_000);
        const onData = (chunk: Buffer) => {
            output += chunk.toString();
            const m = /listening on (http:\/\/[^\s]+)/.exec(output);
            if (m) {
                clearTimeout(timer);
                resolveUrl(m[1].replace(/\/$/, ''));
            }
        };
        server.stdout.on('data', onData);
        server.stderr.on('data', (chunk: Buffer) => { output += chunk.toString(); });
        server.on('exit', (code) => { clearTimeout(timer); reject(new Error(`e2e: server exited (${code}):\n${output}`)); });
    });
    server.stdout.removeAllListeners('data');
    server.stdout.resume();
    server.stderr.resume();

    const login = await post(`${url}/api/v1/auth/login`, { username: 'admin', password: ADMIN_PASSWORD });
    if (!login.ok) throw new Error(`e2e: admin login failed: ${login.status} ${await login.text()}`);
    const { token } = await login.json() as { token: string };
    for (const [username, password] of Object.entries(USERS)) {
        const created = await post(`${url}/api/v1/users`, { username, password, role: 'user' }, token);
        if (created.status !== 201) throw new Error(`e2e: creating ${username}: ${created.status} ${await created.text()}`);
    }
    process.env.TLMHUB_E2E_URL = url;

    return async () => {
        server.kill('SIGTERM');
        await new Promise((r) => { server.once('exit', r); setTimeout(r, 5000); });
        rmSync(dataDir, { recursive: true, force: true });
    };
}
