// The app's socket survives the loss of its API node: the connection is dropped under a long
// run (as when the node behind nginx goes away), the next attempts fail for a while, then a
// new socket opens; the editor shows "reconnecting…", then "connected", opens its model
// again, subscribes to the run again and ends with exactly the job's stored samples.
import { copyFileSync, mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect, type WebSocketRoute } from './fixtures';
import { api, login, openExample, plotted, plotVariable, setRunField } from './helpers';
import type { ResultsJson } from '../src/protocol/types';

const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

test('a dropped socket reconnects, resubscribes to the running job and the plot ends on the stored result', async ({ page, request }) => {
    // Every socket of the page goes through this route: the first is forwarded to the server
    // and dropped by the "node"; while `down`, attempts are refused; then they are forwarded again.
    const servers: WebSocketRoute[] = [];
    const pages: WebSocketRoute[] = [];
    let down = false;
    let refused = 0;
    const sentOnSocket: string[][] = [];
    await page.routeWebSocket(/\/api\/v1\/ws/, (ws) => {
        if (down) {
            refused += 1;
            void ws.close({ code: 1011, reason: 'node unavailable' });
            return;
        }
        const sent: string[] = [];
        sentOnSocket.push(sent);
        const server = ws.connectToServer();
        ws.onMessage((message) => {
            if (typeof message === 'string') sent.push(message);
            server.send(message);
        });
        servers.push(server);
        pages.push(ws);
    });

    await login(page, 'alice');
    const modelId = await openExample(page, 'Position Servo');
    const variable = await plotVariable(page, 'Position_Sensor', 'out', 'Value');
    await setRunField(page, 'Stop time', '1000');
    await page.getByTestId('run').click();
    const status = page.getByTestId('run-status');
    const connection = page.getByTestId('connection-status');
    await page.waitForFunction(() => {
        const s = document.querySelector('[data-testid="run-status"]') as HTMLElement | null;
        const plot = document.querySelector('.plot-window') as HTMLElement | null;
        return s?.dataset.state === 'running' && Number(plot?.dataset.points ?? 0) > 10;
    }, undefined, { timeout: 30_000 });
    const job = Number(await status.getAttribute('data-job'));
    const before = (await plotted(page, variable)).length;

    // the API node goes away: its side closes (1001), and for a while no node answers
    down = true;
    await servers[0].close({ code: 1001, reason: 'going away' });
    await pages[0].close({ code: 1001, reason: 'going away' });
    await expect(connection).toHaveAttribute('data-state', 'reconnecting');
    await expect(connection).toHaveText('reconnecting…');
    await expect.poll(() => refused, { timeout: 15_000 }).toBeGreaterThanOrEqual(2);
    await expect(status).toHaveAttribute('data-state', 'running');   // the run goes on on the server
    mkdirSync(screenshots, { recursive: true });
    mkdirSync(docsScreenshots, { recursive: true });
    await page.screenshot({ path: `${screenshots}ws-reconnecting.png` });
    copyFileSync(`${screenshots}ws-reconnecting.png`, `${docsScreenshots}ws-reconnecting.png`);

    // a node answers again
    down = false;
    await expect(connection).toHaveAttribute('data-state', 'connected', { timeout: 20_000 });
    await expect(connection).toHaveText('connected');
    expect(servers.length).toBe(2);
    const resent = sentOnSocket[1].map((m) => JSON.parse(m) as { type: string; job_id?: number; model_id?: number; frames?: string });
    expect(resent.find((m) => m.type === 'log.subscribe')).toMatchObject({ job_id: job, frames: 'binary' });
    expect(resent.find((m) => m.type === 'model.open')).toMatchObject({ model_id: modelId });

    await expect(status).toHaveAttribute('data-state', 'done', { timeout: 90_000 });
    const results = await api<ResultsJson>(request, page, `/jobs/${job}/results?format=json&variables=${encodeURIComponent(variable)}`);
    const stored = results.variables.find((v) => v.name === variable)!.data;
    expect(before).toBeLessThan(stored.length);
    await expect.poll(async () => (await plotted(page, variable)).length).toBe(stored.length);
    expect(await plotted(page, variable)).toEqual(stored);
    // the streamed samples were complete: the stored result did not have to replace them
    const gap = await page.evaluate(() => (window as unknown as { __tlmhub: { runs: { current: { gap: boolean } } } }).__tlmhub.runs.current.gap);
    expect(gap).toBe(false);

    // the model is open on the new socket with the unsaved change (the stop time) sent again
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'true');
    await expect(page.getByLabel('Stop time', { exact: true })).toHaveValue('1000');
    await expect(page.locator('#toasts .toast-error')).toHaveCount(0);
    await setRunField(page, 'Stop time', '2');
    await page.getByLabel('Stop time', { exact: true }).press('Tab');
    await page.getByTestId('run').click();
    await expect(status).not.toHaveAttribute('data-job', String(job), { timeout: 30_000 });
    await expect(status).toHaveAttribute('data-state', 'done', { timeout: 30_000 });
});
