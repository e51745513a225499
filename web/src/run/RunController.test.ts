import { describe, expect, it, vi } from 'vitest';
import { RunController } from './RunController';
import type { JobInfo, ResultsJson, ServerEvent } from '../protocol/types';
import { ApiError } from '../api/ApiError';
import { MAX_GENERATIONS } from './generations';

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

    it('a history that comes while a run is being started does not take its place', async () => {
        const f = fakeTransport();
        let answer: (reply: { job_id: number }) => void = () => {};
        f.transport.request = (() => new Promise((resolve) => { answer = resolve; })) as never;
        const runs = new RunController(f.transport);
        const starting = runs.start({}, []);
        runs.restore([stored(7), stored(5)]);
        expect(runs.current).toBeNull();
        answer({ job_id: 10 });
        await starting;
        expect(runs.current?.jobId).toBe(10);
        expect(runs.previous?.jobId).toBe(7);
        expect(runs.generations.map((r) => r.jobId)).toEqual([5, 7, 10]);
    });

    it('a run a component of the model ended is done, with the reason it gives', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        const run = await runs.start({}, []);
        f.emit({ type: 'event.done', job_id: 10, state: 'done', stop_reason: 'Simulation stopped by Stop_simulation' });
        expect(run.state).toBe('done');
        expect(run.stopReason).toBe('Simulation stopped by Stop_simulation');
        expect(run.error).toBe('');
    });

    it('a restored run keeps the reason a component of the model ended it', () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([{ ...stored(7), stop_reason: 'Simulation stopped by Stop_simulation' }, stored(5)]);
        expect(runs.current?.stopReason).toBe('Simulation stopped by Stop_simulation');
        expect(runs.previous?.stopReason).toBe('');
    });

    it('a failed run takes what it stored up to the failure, for streamed variables and those asked for later', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        const run = await runs.start({}, ['A#out#Value']);
        f.emit({ type: 'event.frame', job_id: 10, seq: 0, time: [0], variables: { 'A#out#Value': [1] }, dropped: 0 });
        f.emit({ type: 'event.done', job_id: 10, state: 'failed', error: 'step 3: pressure is not a number' });
        expect(run.error).toBe('step 3: pressure is not a number');
        await vi.waitFor(() => expect(run.columns.get('A#out#Value')).toEqual([42, 43]));
        await runs.ensure(['B#p#Pressure']);
        expect(f.results).toHaveBeenCalledWith(10, ['B#p#Pressure']);
        expect(run.columns.get('B#p#Pressure')).toEqual([42, 43]);
    });

    it('a failed run that stored nothing keeps what it streamed, without an error', async () => {
        const f = fakeTransport();
        f.results.mockRejectedValue(new ApiError('not_found', 'no results', 404));
        const runs = new RunController(f.transport);
        const run = await runs.start({}, ['A#out#Value']);
        f.emit({ type: 'event.frame', job_id: 10, seq: 0, time: [0], variables: { 'A#out#Value': [1] }, dropped: 0 });
        f.emit({ type: 'event.done', job_id: 10, state: 'failed', error: 'diverged' });
        await expect(runs.ensure(['A#out#Value', 'B#p#Pressure'])).resolves.toBeUndefined();
        expect(run.columns.get('A#out#Value')).toEqual([1]);
        expect(run.has('B#p#Pressure')).toBe(false);
    });

    it('a done run whose results cannot be read still reports it', async () => {
        const f = fakeTransport();
        f.results.mockRejectedValue(new ApiError('gone', 'results dropped', 410));
        const runs = new RunController(f.transport);
        await runs.start({}, []);
        f.emit({ type: 'event.done', job_id: 10, state: 'done' });
        await expect(runs.ensure(['B#p#Pressure'])).rejects.toThrow('results dropped');
    });

    it('keeps the model\'s runs to step through, oldest first, a refused run not among them', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([stored(5), stored(9, 'failed'), stored(7)]);
        expect(runs.generations.map((r) => r.jobId)).toEqual([5, 7]);
        await runs.start({}, []);
        f.emit({ type: 'event.done', job_id: 10, state: 'done' });
        const request = f.transport.request;
        f.transport.request = (async () => { throw new Error('the job needs 1e+12 steps'); }) as never;
        await expect(runs.start({}, [])).rejects.toThrow();
        f.transport.request = request;
        await runs.start({}, []);
        expect(runs.generations.map((r) => r.jobId)).toEqual([5, 7, 10, 11]);
        expect(runs.generations.at(-1)).toBe(runs.current);
    });

    it('names restored runs by their name in the history, else by their job', () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([{ ...stored(7), name: 'stiff spring' }, stored(5)]);
        expect(runs.generations.map((r) => r.label)).toEqual(['run 5', 'stiff spring']);
    });

    it('keeps at most MAX_GENERATIONS runs, dropping the oldest', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        for (let i = 0; i < MAX_GENERATIONS + 2; ++i) {
            const run = await runs.start({}, []);
            f.emit({ type: 'event.done', job_id: run.jobId, state: 'done' });
        }
        expect(runs.generations).toHaveLength(MAX_GENERATIONS);
        expect(runs.generations[0].jobId).toBe(12);
    });

    it('loads stored results of the runs a plot window shows', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([stored(7), stored(5), stored(3)]);
        await runs.ensure(['B#p#Pressure'], [runs.generations[0]]);
        expect(f.results).toHaveBeenCalledTimes(1);
        expect(f.results).toHaveBeenCalledWith(3, ['B#p#Pressure']);
    });

    it('a run chosen from the history takes its place in time, is shown until a new run starts, and loads its results', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([stored(9), stored(7), stored(5)]);
        const told = vi.fn();
        runs.subscribe(told);
        const choices: number[] = [];
        runs.onChoose((run) => choices.push(run.jobId));
        await runs.choose(stored(5), ['B#p#Pressure']);
        expect(runs.generations.map((r) => r.jobId)).toEqual([5, 7, 9]);
        expect(runs.chosen?.jobId).toBe(5);
        expect(told).toHaveBeenCalled();
        expect(f.results).toHaveBeenCalledWith(5, ['B#p#Pressure']);
        expect(runs.chosen?.columns.get('B#p#Pressure')).toEqual([42, 43]);
        expect(runs.current?.jobId).toBe(9);   // still the run the status names

        // one no longer among them joins them, with its name, its state and its error
        await runs.choose({ ...stored(2, 'failed'), name: 'too stiff', error: 'diverged' }, []);
        const chosen = runs.chosen!;
        expect([chosen.jobId, chosen.label, chosen.state, chosen.error]).toEqual([2, 'too stiff', 'failed', 'diverged']);
        expect(runs.generations.map((r) => r.jobId)).toEqual([2, 5, 7, 9]);
        // the same run again is a choice again (a window may have stepped away from it)
        await runs.choose(stored(5), []);
        expect(choices).toEqual([5, 2, 5]);

        // a new run comes after them and is shown
        await runs.start({}, []);
        expect(runs.generations.map((r) => r.jobId)).toEqual([2, 5, 7, 9, 10]);
        expect(runs.chosen).toBeNull();
    });

    it('a chosen run is not replaced by a history that arrives later', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        await runs.choose(stored(3), []);
        runs.restore([stored(7), stored(5)]);
        expect(runs.generations.map((r) => r.jobId)).toEqual([3]);
    });

    it('runs without results cannot be chosen: dropped, cancelled or still running', async () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([stored(7)]);
        for (const job of [{ ...stored(5), results_dropped: true }, stored(4, 'cancelled'), stored(3, 'running')]) await runs.choose(job, ['B#p#Pressure']);
        expect(runs.generations.map((r) => r.jobId)).toEqual([7]);
        expect(f.results).not.toHaveBeenCalled();
    });

    it('a renamed run names its curves by the new name, or by its job when the name is taken away', () => {
        const f = fakeTransport();
        const runs = new RunController(f.transport);
        runs.restore([stored(7), stored(5)]);
        const told = vi.fn();
        runs.subscribe(told);
        runs.rename({ ...stored(5), name: 'baseline' });
        expect(runs.generations.map((r) => r.label)).toEqual(['baseline', 'run 7']);
        runs.rename(stored(5));
        expect(runs.generations[0].label).toBe('run 5');
        expect(told).toHaveBeenCalledTimes(2);
    });
});
