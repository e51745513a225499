import { describe, expect, it, vi } from 'vitest';
import { RunController } from './RunController';
import type { JobInfo, ResultsJson, ServerEvent } from '../protocol/types';

/** A run of the history as GET /jobs?model_id= lists it. */
const stored = (id: number, state: JobInfo['state'] = 'done'): JobInfo => ({
    id, model_id: 4, state, progress: 1, error: '', created_at: 0, started_at: 0, finished_at: 1, steps: 100,
    settings: { start: 0, step: 0.001, stop: 1, log_samples: 0 }, name: '', pinned: false, results_dropped: false,
});

function fakeTransport() {
    let listener: ((e: ServerEvent) => void) | null = null;
    let nextJob = 10;
    const sent: { type: string; fields: Record<string, unknown> }[] = [];
    const results = vi.fn(async (_id: number, names: string[]): Promise<ResultsJson> => ({
        time: [0, 1], variables: names.map((n) => ({ name: n, unit: '', data: [42, 43] })),
    }));
    return {
        sent,
        results,
        emit: (e: ServerEvent) => listener?.(e),
        transport: {
            request: (async (type: string, fields: Record<string, unknown> = {}) => {
                sent.push({ type, fields });
                return type === 'simulate.start' ? { job_id: nextJob++ } : { state: 'cancelled' };
            }) as never,
            onEvent: (l: (e: ServerEvent) => void) => { listener = l; return () => { listener = null; }; },
            resultsJson: results,
        },
    };
}

describe('RunController', () => {
    it('starts a run streaming the chosen variables and fills it from events', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        const run = await runs.start({ stop: 2 }, ['A#out#Value']);
        expect(f.sent[0]).toEqual({ type: 'simulate.start', fields: { frames: 'binary', stop: 2, rate: 30, variables: ['A#out#Value'] } });
        f.emit({ type: 'event.progress', job_id: 10, progress: 0.5 });
        f.emit({ type: 'event.frame', job_id: 10, seq: 0, time: [0, 1], variables: { 'A#out#Value': [1, 2] }, dropped: 0 });
        expect(runs.running).toBe(true);
        f.emit({ type: 'event.done', job_id: 10, state: 'done' });
        expect(run.progress).toBe(1);
        expect(run.columns.get('A#out#Value')).toEqual([1, 2]);
        expect(runs.running).toBe(false);
    });

    it('streams at most 16 variables', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        await runs.start({}, Array.from({ length: 20 }, (_, i) => `V${i}#p#Value`));
        expect((f.sent[0].fields.variables as string[]).length).toBe(16);
    });

    it('keeps the finished run as the previous one for comparison', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        await runs.start({}, []);
        f.emit({ type: 'event.done', job_id: 10, state: 'done' });
        await runs.start({}, []);
        expect(runs.previous?.jobId).toBe(10);
        expect(runs.current?.jobId).toBe(11);
    });

    it('loads stored results of finished runs for variables that were not streamed', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        await runs.start({}, []);
        f.emit({ type: 'event.done', job_id: 10, state: 'done' });
        await runs.ensure(['B#p#Pressure']);
        expect(f.results).toHaveBeenCalledWith(10, ['B#p#Pressure']);
        expect(runs.current?.columns.get('B#p#Pressure')).toEqual([42, 43]);
    });

    it('after event.resync it ignores frames and replaces the streamed samples with the stored result at the end', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        const run = await runs.start({}, ['A#out#Value']);
        f.emit({ type: 'event.frame', job_id: 10, seq: 0, time: [0], variables: { 'A#out#Value': [1] }, dropped: 3 });
        expect(run.gap).toBe(false);   // merged frames keep their samples
        f.emit({ type: 'event.resync', job_id: 10 });
        f.emit({ type: 'event.frame', job_id: 10, seq: 1, time: [0.5], variables: { 'A#out#Value': [9] }, dropped: 0 });
        expect(run.columns.get('A#out#Value')).toEqual([1]);
        expect(f.results).not.toHaveBeenCalled();   // the stored result exists once the job ends
        f.emit({ type: 'event.done', job_id: 10, state: 'done' });
        await vi.waitFor(() => expect(run.columns.get('A#out#Value')).toEqual([42, 43]));
        expect(f.results).toHaveBeenCalledWith(10, ['A#out#Value']);
        expect(run.time).toEqual([0, 1]);
        expect(run.gap).toBe(false);
    });

    it('a resync before any frame of an all-variables run leaves the loading to ensure()', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        await runs.start({}, []);
        f.emit({ type: 'event.resync', job_id: 10 });
        f.emit({ type: 'event.done', job_id: 10, state: 'done' });
        expect(f.results).not.toHaveBeenCalled();
        await runs.ensure(['B#p#Pressure']);
        expect(runs.current?.columns.get('B#p#Pressure')).toEqual([42, 43]);
    });

    it('cancel sends simulate.stop for the running job', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        await runs.start({}, []);
        await runs.cancel();
        expect(f.sent[1]).toEqual({ type: 'simulate.stop', fields: { job_id: 10 } });
        f.emit({ type: 'event.done', job_id: 10, state: 'cancelled' });
        expect(runs.current?.state).toBe('cancelled');
    });

    it('restores the last two finished runs of the history and loads their results when plots ask', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        const told = vi.fn();
        runs.subscribe(told);
        runs.restore([stored(9, 'failed'), stored(7), stored(5)]);
        expect(told).toHaveBeenCalled();
        expect(runs.running).toBe(false);
        expect(runs.current?.jobId).toBe(7);
        expect(runs.current?.state).toBe('done');
        expect(runs.current?.finished).toBe(true);
        expect(runs.previous?.jobId).toBe(5);
        await runs.ensure(['B#p#Pressure']);
        expect(f.results).toHaveBeenCalledWith(7, ['B#p#Pressure']);
        expect(f.results).toHaveBeenCalledWith(5, ['B#p#Pressure']);
        expect(runs.current?.columns.get('B#p#Pressure')).toEqual([42, 43]);
    });

    it('a history that arrives after a run was started changes nothing', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        await runs.start({}, []);
        runs.restore([stored(7)]);
        expect(runs.current?.jobId).toBe(10);
        expect(runs.previous).toBeNull();
    });

    it('a run started after the restore keeps the restored run to compare with', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([stored(7)]);
        await runs.start({}, []);
        expect(runs.current?.jobId).toBe(10);
        expect(runs.previous?.jobId).toBe(7);
    });
});
