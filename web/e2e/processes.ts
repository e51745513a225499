// Starting the processes a spec needs beside the shared e2e server: a second tlmhub-server
// with other flags, a test peer (an OpenID provider, an LTI platform).
import { spawn, type ChildProcess } from 'node:child_process';
import { createServer } from 'node:net';

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
