// Reconnecting: the backoff schedule (full jitter over a capped doubling, started over after a
// connection that stayed up), no reconnect after an intentional close or the end of the login,
// subscriptions to unfinished jobs renewed, pending requests rejected, and a run's data that
// comes out exactly as an uninterrupted stream would give it.
import { describe, expect, it } from 'vitest';
import { backoffDelay, WsClient, type ReconnectOptions } from './WsClient';
import { ApiError } from './ApiError';
import { RunController } from '../run/RunController';
import type { ResultsJson } from '../protocol/types';
import { FakeSocket as SharedFakeSocket } from '../testing/FakeSocket';

class FakeSocket extends SharedFakeSocket {
    closedByClient = false;
    override close() { this.closedByClient = true; }
    /** The connection is lost (the browser's close event; 1006: no close frame). */
    drop(code = 1006) { this.onclose?.({ code }); }
    hello() { this.receive({ type: 'hello', protocol: 'tlmhub.v1', user: { id: 1, username: 'alice', role: 'user' } }); }
    reply(index: number, data: unknown = {}) { this.receive({ id: this.sent[index].id, type: 'reply', ok: true, data }); }
    of(type: string) { return this.sent.filter((m) => m.type === type); }
}

/** A client on fake sockets, with a manual clock, timers and random source. */
function harness(options: Partial<ReconnectOptions> = {}, random = () => 0.5) {
    const sockets: FakeSocket[] = [];
    const timers: { fn: () => void; ms: number; cleared: boolean }[] = [];
    let now = 0;
    const client = new WsClient(() => {
        const s = new FakeSocket();
        sockets.push(s);
        return s;
    }, {
        random,
        setTimer: (fn, ms) => { const t = { fn, ms, cleared: false }; timers.push(t); return t; },
        clearTimer: (t) => { (t as { cleared: boolean }).cleared = true; },
        now: () => now,
        ...options,
    });
    const statuses: string[] = [];
    client.onStatus((s) => statuses.push(s));
    return {
        client, sockets, timers, statuses,
        get socket() { return sockets[sockets.length - 1]; },
        advance(ms: number) { now += ms; },
        /** Fires the last timer and lets the reconnect's promises settle. */
        async fire() {
            const t = timers[timers.length - 1];
            expect(t.cleared).toBe(false);
            t.fn();
            await flush();
        },
        delays() { return timers.map((t) => t.ms); },
    };
}

const flush = () => new Promise((r) => setTimeout(r, 0));

async function connectedHarness(options: Partial<ReconnectOptions> = {}, random?: () => number) {
    const h = harness(options, random);
    const ready = h.client.connect();
    h.socket.hello();
    await ready;
    return h;
}

describe('backoffDelay', () => {
    it('is uniform below a ceiling that doubles from 250 ms to 10 s', () => {
        const top = () => 0.999999;
        expect(Array.from({ length: 9 }, (_, i) => backoffDelay(i, top))).toEqual([249, 499, 999, 1999, 3999, 7999, 9999, 9999, 9999]);
        expect(backoffDelay(3, () => 0)).toBe(0);
        expect(backoffDelay(2, () => 0.5)).toBe(500);
        expect(backoffDelay(1000, () => 0.5)).toBe(5000);   // no overflow for long outages
    });
});

describe('WsClient reconnecting', () => {
    it('backs off with full jitter while attempts fail, and starts over after a connection that stayed up', async () => {
        const h = await connectedHarness({ stableMs: 5000 });
        expect(h.statuses).toEqual(['connected']);
        h.socket.drop();
        expect(h.client.status).toBe('reconnecting');
        for (let i = 0; i < 7; ++i) {
            await h.fire();
            h.socket.drop();   // the server is still away: closed before hello
        }
        // random() = 0.5: half of 250, 500, 1000, ... capped at 10 s
        expect(h.delays()).toEqual([125, 250, 500, 1000, 2000, 4000, 5000, 5000]);
        await h.fire();
        h.socket.hello();
        await flush();
        expect(h.client.status).toBe('connected');
        // a connection that did not stay up goes on with the next delay ...
        h.advance(1000);
        h.socket.drop();
        expect(h.delays().at(-1)).toBe(5000);
        await h.fire();
        h.socket.hello();
        await flush();
        // ... one that stayed up starts over
        h.advance(5000);
        h.socket.drop();
        expect(h.delays().at(-1)).toBe(125);
        expect(h.statuses).toEqual(['connected', 'reconnecting', 'connected', 'reconnecting', 'connected', 'reconnecting']);
    });

    it('the random source decides within the ceiling (full jitter)', async () => {
        const values = [0.1, 0.9, 0.3];
        const h = await connectedHarness({}, () => values.shift()!);
        h.socket.drop();
        await h.fire();
        h.socket.drop();
        await h.fire();
        h.socket.drop();
        expect(h.delays()).toEqual([25, 450, 300]);
    });

    it('does not reconnect after close() (leaving the page, logging out)', async () => {
        const h = await connectedHarness();
        const socket = h.socket;
        h.client.close();
        expect(socket.closedByClient).toBe(true);
        socket.drop(1000);   // the browser's close event after our close(): ignored
        expect(h.timers).toEqual([]);
        expect(h.sockets.length).toBe(1);
        expect(h.client.status).toBe('closed');
    });

    it('close() while waiting to reconnect cancels the attempt', async () => {
        const h = await connectedHarness();
        h.socket.drop();
        h.client.close();
        expect(h.timers[0].cleared).toBe(true);
        h.timers[0].fn();
        await flush();
        expect(h.sockets.length).toBe(1);
    });

    it('does not reconnect when the server ended the login (close code 1008), and says so', async () => {
        const h = await connectedHarness();
        const reasons: string[] = [];
        h.client.onClose((r) => reasons.push(r));
        h.socket.drop(1008);
        expect(h.timers).toEqual([]);
        expect(reasons).toEqual(['auth']);
        expect(h.client.status).toBe('closed');
    });

    it('with a login check, a 1008 close asks it: a role change reconnects, an ended login stops', async () => {
        let loggedIn = true;
        const h = await connectedHarness({ shouldReconnect: () => loggedIn });
        const reasons: string[] = [];
        h.client.onClose((r) => reasons.push(r));
        h.socket.drop(1008);   // role changed
        await h.fire();
        h.socket.hello();
        await flush();
        expect(h.client.status).toBe('connected');
        loggedIn = false;
        h.socket.drop(1008);   // logged out
        await h.fire();
        expect(h.sockets.length).toBe(2);
        expect(reasons).toEqual(['auth']);
    });

    it('stops when shouldReconnect says the login is gone (a refused upgrade tells the browser nothing)', async () => {
        let loggedIn = true;
        const h = await connectedHarness({ shouldReconnect: () => loggedIn });
        const reasons: string[] = [];
        h.client.onClose((r) => reasons.push(r));
        h.socket.drop();
        await h.fire();
        h.socket.drop();
        loggedIn = false;
        await h.fire();
        expect(h.sockets.length).toBe(2);
        expect(reasons).toEqual(['auth']);
        expect(h.client.status).toBe('closed');
    });

    it('rejects the requests the lost socket never answered, and new ones while reconnecting', async () => {
        const h = await connectedHarness();
        const edit = h.client.request('component.move', { name: 'X', pose: { x: 1, y: 2, angle: 0, flipped: false } });
        const ping = h.client.request('ping');
        h.socket.drop();
        const err = await edit.catch((e: unknown) => e);
        expect(err).toBeInstanceOf(ApiError);
        expect(err).toMatchObject({ code: 'connection_lost' });
        expect((err as Error).message).toMatch(/component\.move: the connection to the server was lost/);
        await expect(ping).rejects.toMatchObject({ code: 'connection_lost' });
        await expect(h.client.request('ping')).rejects.toMatchObject({ code: 'not_connected', message: expect.stringMatching(/reconnecting/) });
        // after the reconnect requests go out on the new socket
        await h.fire();
        h.socket.hello();
        await flush();
        const again = h.client.request('ping');
        h.socket.reply(0);
        await expect(again).resolves.toEqual({});
    });

    it('subscribes again to the jobs without event.done only, with their fields, then restores the page state', async () => {
        const h = await connectedHarness();
        const first = h.socket;
        const started = h.client.request('simulate.start', { stop: 100, variables: ['A#out#Value'], frames: 'binary', rate: 30 });
        first.reply(0, { job_id: 5 });
        await started;
        const followed = h.client.request('log.subscribe', { job_id: 6 });
        first.reply(1);
        await followed;
        const finished = h.client.request('simulate.start', {});
        first.receive({ type: 'event.done', job_id: 7, state: 'done' });   // overtakes its reply
        first.reply(2, { job_id: 7 });
        await finished;
        const done = h.client.request('log.subscribe', { job_id: 8 });
        first.reply(3);
        await done;
        first.receive({ type: 'event.done', job_id: 8, state: 'failed', error: 'x' });
        expect(h.client.activeSubscriptions.sort()).toEqual([5, 6]);

        const resubscribed: number[] = [];
        h.client.onResubscribe((job) => resubscribed.push(job));
        let restored = 0;
        h.client.onReconnect(async () => {
            await h.client.request('model.open', { model_id: 3 });
            restored += 1;
        });
        first.drop();
        await h.fire();
        const second = h.socket;
        expect(second).not.toBe(first);
        second.hello();
        await flush();
        expect(resubscribed.sort()).toEqual([5, 6]);
        expect(second.of('log.subscribe').map(({ id: _, ...m }) => m)).toEqual([
            { type: 'log.subscribe', job_id: 5, variables: ['A#out#Value'], frames: 'binary', rate: 30 },
            { type: 'log.subscribe', job_id: 6 },
        ]);
        expect(second.of('model.open')).toMatchObject([{ model_id: 3 }]);
        expect(h.client.status).toBe('reconnecting');   // until all is restored
        for (let i = 0; i < second.sent.length; ++i) second.reply(i);
        await flush();
        expect(restored).toBe(1);
        expect(h.client.status).toBe('connected');
        // a job that ends is not subscribed again on the next reconnect
        second.receive({ type: 'event.done', job_id: 5, state: 'done' });
        second.drop();
        await h.fire();
        h.socket.hello();
        await flush();
        expect(h.socket.of('log.subscribe').map((m) => m.job_id)).toEqual([6]);
    });

    it('keeps a subscription whose renewal was cut short by another drop', async () => {
        const h = await connectedHarness();
        const sub = h.client.request('log.subscribe', { job_id: 9 });
        h.socket.reply(0);
        await sub;
        h.socket.drop();
        await h.fire();
        h.socket.hello();
        h.socket.drop();   // before the reply to log.subscribe
        await flush();
        expect(h.client.activeSubscriptions).toEqual([9]);
        await h.fire();
        h.socket.hello();
        await flush();
        expect(h.socket.of('log.subscribe')).toMatchObject([{ job_id: 9 }]);
    });

    it('forgets a subscription the server refuses after the reconnect (a deleted job)', async () => {
        const h = await connectedHarness();
        const sub = h.client.request('log.subscribe', { job_id: 9 });
        h.socket.reply(0);
        await sub;
        h.socket.drop();
        await h.fire();
        h.socket.hello();
        await flush();
        const s = h.socket;
        s.receive({ id: s.sent[0].id, type: 'error', error: { code: 'not_found', message: 'no job 9' } });
        await flush();
        expect(h.client.activeSubscriptions).toEqual([]);
        expect(h.client.status).toBe('connected');
    });
});

// ---- a run's data across a reconnect ----

/** Builds a binary frame as protocol/README.md describes it. */
function encodeFrame(jobId: number, seq: number, time: number[], variables: Record<string, number[]>): ArrayBuffer {
    const header = {
        type: 'event.frame', job_id: jobId, seq, dropped: 0, time_samples: time.length,
        variables: Object.entries(variables).map(([name, v]) => ({ name, samples: v.length })),
    };
    const text = new TextEncoder().encode(JSON.stringify(header));
    const dataOffset = Math.ceil((4 + text.length) / 8) * 8;
    const columns = [time, ...Object.values(variables)];
    const buffer = new ArrayBuffer(dataOffset + columns.reduce((n, c) => n + c.length, 0) * 8);
    const view = new DataView(buffer);
    view.setUint32(0, text.length, true);
    new Uint8Array(buffer, 4, text.length).set(text);
    let at = dataOffset;
    for (const column of columns) for (const x of column) { view.setFloat64(at, x, true); at += 8; }
    return buffer;
}

const N = 60;
const series = {
    time: Array.from({ length: N }, (_, i) => i * 0.01),
    'A#out#Value': Array.from({ length: N }, (_, i) => Math.sin(i / 7)),
    'B#out#Value': Array.from({ length: N }, (_, i) => i * i - 3),
};

/**
 * The frames a subscription gets, starting at sample 0: chunks of `size` samples; a variable may
 * lag the time vector by `lag` samples in a frame (the binary header counts each column), as
 * long as the frames together carry everything.
 */
function* stream(jobId: number, size: number, lag: number, binary: boolean) {
    let seq = 0;
    for (let from = 0; from < N; from += size) {
        const to = Math.min(N, from + size);
        const vFrom = Math.max(0, from - lag);
        const vTo = to === N ? N : Math.max(0, to - lag);
        const variables = {
            'A#out#Value': series['A#out#Value'].slice(vFrom, vTo),
            'B#out#Value': series['B#out#Value'].slice(from, to),
        };
        const time = series.time.slice(from, to);
        yield binary ? encodeFrame(jobId, seq, time, variables) : { type: 'event.frame', job_id: jobId, seq, time, variables, dropped: 0 };
        seq += 1;
    }
}

describe('a run across a reconnect', () => {
    for (const binary of [true, false]) {
        it(`keeps exactly the uninterrupted series, no duplicates, no gaps (${binary ? 'binary' : 'JSON'} frames)`, async () => {
            const h = await connectedHarness();
            const stored = { calls: 0 };
            const runs = new RunController({
                request: h.client.request.bind(h.client), onEvent: h.client.onEvent.bind(h.client),
                onResubscribe: h.client.onResubscribe.bind(h.client),
                resultsJson: async (): Promise<ResultsJson> => { stored.calls += 1; return { time: [], variables: [] }; },
            });
            const starting = runs.start({ stop: 0.6 }, ['A#out#Value', 'B#out#Value']);
            h.socket.reply(0, { job_id: 41 });
            const run = await starting;
            // frames 0..3 (7 samples each) arrive, then the connection is lost
            const before = [...stream(41, 7, 2, binary)].slice(0, 4);
            for (const frame of before) h.socket.receive(frame);
            expect(run.time.length).toBe(28);
            expect(run.columns.get('A#out#Value')!.length).toBe(26);   // a column may lag the time vector
            h.socket.drop();
            await h.fire();
            h.socket.hello();
            await flush();
            expect(h.socket.of('log.subscribe')).toMatchObject([{ job_id: 41, variables: ['A#out#Value', 'B#out#Value'], frames: 'binary' }]);
            h.socket.reply(0);
            // the new subscription starts again at seq 0 and sample 0, cut into other frames
            for (const frame of stream(41, 5, 3, binary)) h.socket.receive(frame);
            h.socket.receive({ type: 'event.done', job_id: 41, state: 'done' });
            await flush();
            expect(run.state).toBe('done');
            expect(run.time).toEqual(series.time);
            expect(run.columns.get('A#out#Value')).toEqual(series['A#out#Value']);
            expect(run.columns.get('B#out#Value')).toEqual(series['B#out#Value']);
            expect(run.gap).toBe(false);        // the stream was complete: no download needed
            expect(stored.calls).toBe(0);
            runs.dispose();
        });
    }
});
