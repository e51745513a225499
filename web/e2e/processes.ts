// Starting the processes a spec needs beside the shared e2e server: a second tlmhub-server
// with other flags, a test peer (an OpenID provider, an LTI platform) and its certificates.
import { execFileSync, spawn, type ChildProcess } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { join } from 'node:path';

/** A loopback port free now. */
export function freePort(): Promise<number> {
    return new Promise((done, fail) => {
        const probe = createServer();
        probe.once('error', fail);
        probe.listen(0, '127.0.0.1', () => {
            const { port } = probe.address() as { port: number };
            probe.close(() => done(port));
        });
    });
}

/** Starts `command` and resolves once its output matches `ready`. */
export function started(command: string, args: string[], ready: RegExp, env: NodeJS.ProcessEnv = process.env): Promise<ChildProcess> {
    return new Promise((done, fail) => {
        const child = spawn(command, args, { env, stdio: ['ignore', 'pipe', 'pipe'] });
        let output = '';
        const timer = setTimeout(() => fail(new Error(`${command} did not start:\n${output}`)), 30_000);
        const read = (chunk: Buffer) => {
            output += chunk.toString();
            if (ready.test(output)) {
                clearTimeout(timer);
                child.stdout!.removeAllListeners('data');
                child.stdout!.resume();
                child.stderr!.resume();
                done(child);
            }
        };
        child.stdout!.on('data', read);
        child.stderr!.on('data', read);
        child.on('exit', (code) => { clearTimeout(timer); fail(new Error(`${command} exited (${code}):\n${output}`)); });
    });
}

/** Writes into `dir` a CA (ca.pem) and a certificate for 127.0.0.1 it signed (cert.pem, key.pem):
 * what a test peer serves TLS with, and what the server under test trusts it by. */
export function makeTestCertificates(dir: string): void {
    const openssl = (...args: string[]) => execFileSync('openssl', args, { cwd: dir, stdio: 'ignore' });
    openssl('req', '-x509', '-newkey', 'rsa:2048', '-nodes', '-keyout', 'ca.key', '-out', 'ca.pem', '-days', '2', '-subj', '/CN=e2e CA');
    openssl('req', '-newkey', 'rsa:2048', '-nodes', '-keyout', 'key.pem', '-out', 'request.csr', '-subj', '/CN=127.0.0.1');
    writeFileSync(join(dir, 'san.ext'), 'subjectAltName=IP:127.0.0.1\n');
    openssl('x509', '-req', '-in', 'request.csr', '-CA', 'ca.pem', '-CAkey', 'ca.key', '-CAcreateserial', '-out', 'cert.pem',
        '-days', '2', '-extfile', 'san.ext');
}
