import { describe, expect, it } from 'vitest';
import { RestClient } from './RestClient';
import { ApiError } from './ApiError';

/** A fetch that answers from a list, in order, and records what it was asked. */
function scripted(answers: (() => Response)[]) {
    const asked: { url: string; method: string; body?: BodyInit | null }[] = [];
    const fetchFn = (async (url: string, init: RequestInit) => {
        asked.push({ url, method: init.method ?? 'GET', body: init.body });
        const next = answers.shift();
        if (!next) throw new Error('no more answers');
        return next();
    }) as unknown as typeof fetch;
    return { asked, fetchFn };
}

const busy = (retryAfter = '1') => () => new Response(JSON.stringify({ error: { code: 'busy', message: 'at most 2 large replies' } }),
    { status: 503, headers: { 'Retry-After': retryAfter } });
const ok = (body: unknown) => () => new Response(JSON.stringify(body), { status: 200 });

describe('RestClient', () => {
    it('sends a GET again after the Retry-After of a busy refusal', async () => {
        const { asked, fetchFn } = scripted([busy('2'), busy('1'), ok({ id: 7 })]);
        const waits: number[] = [];
        const client = new RestClient('t', '/api/v1', fetchFn, async (ms) => { waits.push(ms); });
        const job = await client.job(7);
        expect(job).toEqual({ id: 7 });
        expect(waits).toEqual([2000, 1000]);
        expect(asked.map((a) => a.url)).toEqual(['/api/v1/jobs/7', '/api/v1/jobs/7', '/api/v1/jobs/7']);
    });

    it('gives up after three more tries and reports the refusal', async () => {
        const { asked, fetchFn } = scripted([busy(), busy(), busy(), busy()]);
        const client = new RestClient('t', '/api/v1', fetchFn, async () => undefined);
        const err = await client.getModel(3).catch((e: unknown) => e);
        expect(err).toBeInstanceOf(ApiError);
        expect((err as ApiError).code).toBe('busy');
        expect(asked).toHaveLength(4);
    });

    it('never repeats a request that changes something, nor waits for a long Retry-After', async () => {
        const post = scripted([busy()]);
        const client = new RestClient('t', '/api/v1', post.fetchFn, async () => undefined);
        expect(((await client.createModel('m').catch((e: unknown) => e)) as ApiError).code).toBe('busy');
        expect(post.asked).toHaveLength(1);

        const long = scripted([busy('600')]);
        const waits: number[] = [];
        const reader = new RestClient('t', '/api/v1', long.fetchFn, async (ms) => { waits.push(ms); });
        expect(((await reader.job(1).catch((e: unknown) => e)) as ApiError).code).toBe('busy');
        expect(waits).toEqual([]);
    });

    it('asks for a model\'s run history with the page size and the job to continue after', async () => {
        const runs = [{ id: 12, state: 'done' }, { id: 9, state: 'failed' }];
        const { asked, fetchFn } = scripted([ok(runs), ok([])]);
        const client = new RestClient('t', '/api/v1', fetchFn);
        expect(await client.runHistory(4)).toEqual(runs);
        expect(await client.runHistory(4, 20, 9)).toEqual([]);
        expect(asked).toEqual([
            { url: '/api/v1/jobs?model_id=4', method: 'GET', body: undefined },
            { url: '/api/v1/jobs?model_id=4&limit=20&before=9', method: 'GET', body: undefined },
        ]);
    });

    it('names and pins a run with a PATCH of only the fields given', async () => {
        const { asked, fetchFn } = scripted([ok({ id: 12, name: 'baseline', pinned: true })]);
        const client = new RestClient('t', '/api/v1', fetchFn);
        const job = await client.labelJob(12, { name: 'baseline', pinned: true });
        expect(job).toEqual({ id: 12, name: 'baseline', pinned: true });
        expect(asked).toEqual([{ url: '/api/v1/jobs/12', method: 'PATCH', body: JSON.stringify({ name: 'baseline', pinned: true }) }]);
    });

    it('reads the user\'s preferences and replaces them with a PUT of the whole object', async () => {
        const stored = { units: { Pressure: 'bar', Flow: 'l/min' } };
        const { asked, fetchFn } = scripted([ok({ units: {} }), ok(stored)]);
        const client = new RestClient('t', '/api/v1', fetchFn);
        expect(await client.preferences()).toEqual({ units: {} });
        expect(await client.setPreferences(stored)).toEqual(stored);
        expect(asked).toEqual([
            { url: '/api/v1/preferences', method: 'GET', body: undefined },
            { url: '/api/v1/preferences', method: 'PUT', body: JSON.stringify(stored) },
        ]);
    });
});
