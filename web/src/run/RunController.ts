// Runs of the open model: simulate.start over the socket, events into RunData, cancel, and
// the stored results for variables that were not streamed or whose stream the server cut
// short (event.resync). Keeps the previous run to compare, and the model's runs for plot
// windows to step through (generations).
import { RunData } from './RunData';
import type { RestClient } from '../api/RestClient';
import type { WsClient } from '../api/WsClient';
import type { JobInfo, ServerEvent } from '../protocol/types';
import { restorableRuns } from './runHistory';
import { MAX_GENERATIONS, withGeneration } from './generations';
import { ApiError } from '../api/ApiError';
import { DEFAULT_FRAME_RATE, MAX_STREAM_VARIABLES } from '../protocol/constants.generated';
import type { RequestFields } from '../protocol/requests.generated';

export interface RunSettings { start: number; step: number; stop: number; log_samples: number }

/** The socket and REST calls the controller needs (fakes in tests). */
export interface RunTransport {
    request: WsClient['request'];
    onEvent: WsClient['onEvent'];
    resultsJson: RestClient['resultsJson'];
    /** Told when a job is subscribed again after a reconnect (its stream starts over). */
    onResubscribe?: WsClient['onResubscribe'];
}

export class RunController {
    current: RunData | null = null;
    previous: RunData | null = null;
    /** The model's runs a plot window can step through, in the order they were run (job ids). */
    generations: RunData[] = [];
    /** The run the user chose from the history, until a new run starts: the plot windows show it. */
    chosen: RunData | null = null;
    private readonly choiceListeners = new Set<(run: RunData) => void>();
    private readonly early = new Map<number, ServerEvent[]>();
    /** Runs asked for whose job the server has not named yet. */
    private starting = 0;
    private readonly listeners = new Set<() => void>();
    private readonly detach: (() => void)[];

    constructor(private readonly transport: RunTransport) {
        this.detach = [transport.onEvent((event) => this.onEvent(event))];
        if (transport.onResubscribe) this.detach.push(transport.onResubscribe((jobId) => this.onResubscribe(jobId)));
    }

    dispose(): void { for (const d of this.detach) d(); }

    /** The stream of a job starts over after a reconnect: the run keeps what it has and drops the repeat. */
    private onResubscribe(jobId: number): void {
        const run = this.current;
        if (run && run.jobId === jobId) run.restartStream();
        // events of this job held for a simulate.start reply that has not come belong to the old stream
        this.early.delete(jobId);
    }

    subscribe(listener: () => void): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    /** Tells `listener` of each run the user chooses from the history (the same one again, too). */
    onChoose(listener: (run: RunData) => void): () => void {
        this.choiceListeners.add(listener);
        return () => this.choiceListeners.delete(listener);
    }

    get running(): boolean { return this.current !== null && !this.current.finished; }

    /** Starts a run of the socket's open model, streaming `variables` (at most MAX_STREAM_VARIABLES). */
    async start(settings: Partial<RunSettings>, variables: string[], span: [number, number] | null = null): Promise<RunData> {
        const streamed = variables.slice(0, MAX_STREAM_VARIABLES);
        // Binary frames: float64 columns, no number formatting on the server or parsing here.
        const fields: RequestFields<'simulate.start'> = { ...settings, rate: DEFAULT_FRAME_RATE, frames: 'binary' };
        if (streamed.length > 0) fields.variables = streamed;
        this.starting++;
        let reply;
        try {
            reply = await this.transport.request('simulate.start', fields);
        } finally {
            this.starting--;
        }
        if (this.current?.finished) this.previous = this.current;
        const run = new RunData(reply.job_id, streamed);
        run.state = 'running';
        run.span = span;
        this.current = run;
        this.chosen = null;
        this.generations = withGeneration(this.generations, run);
        for (const event of this.early.get(run.jobId) ?? []) this.apply(run, event);
        this.early.clear();
        this.emit();
        return run;
    }

    /**
     * Shows the model's last finished runs from its run history (after a reload, say), unless a
     * run was started or chosen meanwhile. Their data is loaded when plots ask for it (ensure).
     */
    restore(history: JobInfo[]): void {
        if (this.current || this.generations.length > 0) return;
        const restored = restorableRuns(history).slice(0, MAX_GENERATIONS).reverse().map(finishedRun);
        if (restored.length === 0) return;
        this.generations = restored;
        if (this.starting > 0) {
            // A run asked for before the history came is the current one once the server
            // names it; the history's latest is what it is compared with.
            this.previous = restored.at(-1)!;
        } else {
            this.current = restored.at(-1)!;
            this.previous = restored.at(-2) ?? null;
        }
        this.emit();
    }

    /**
     * Shows a run of the model's history in the plot windows: it joins the generations (if not
     * among them) in its place in time, and the windows step to it. Its results for `variables`
     * are loaded. A new run is shown again as it comes.
     */
    async choose(job: JobInfo, variables: string[]): Promise<void> {
        if (!isChoosable(job)) return;
        const run = this.generations.find((r) => r.jobId === job.id) ?? finishedRun(job);
        this.generations = withGeneration(this.generations, run);
        this.chosen = run;
        this.emit();
        for (const l of this.choiceListeners) l(run);
        await this.ensure(variables, [run]);
    }

    /** The user named a run (or took its name away): plots name its curves so. */
    rename(job: JobInfo): void {
        const run = this.generations.find((r) => r.jobId === job.id);
        if (!run) return;
        run.label = runLabel(job);
        this.emit();
    }

    async cancel(): Promise<void> {
        if (!this.current || this.current.finished) return;
        await this.transport.request('simulate.stop', { job_id: this.current.jobId });
    }

    /**
     * Loads stored results of finished runs (by default the current and the previous one) for
     * variables they lack. A failed run keeps what it logged up to the failure, if anything:
     * its results may be missing (404) or dropped (410).
     */
    async ensure(names: string[], runs: (RunData | null)[] = [this.current, this.previous]): Promise<void> {
        const stored = runs.filter((r): r is RunData => r !== null && hasStoredResults(r));
        await Promise.all(stored.map(async (run) => {
            const missing = names.filter((n) => !run.has(n));
            if (missing.length === 0) return;
            try {
                run.setResults(await this.transport.resultsJson(run.jobId, missing));
            } catch (e) {
                if (!(run.state === 'failed' && isNoResults(e))) throw e;
            }
        }));
        this.emit();
    }

    private onEvent(event: ServerEvent): void {
        const run = this.current;
        if (!run || run.jobId !== event.job_id) {
            // events may overtake the reply to simulate.start
            if (!run || event.job_id > run.jobId) {
                const list = this.early.get(event.job_id) ?? [];
                list.push(event);
                this.early.set(event.job_id, list);
            }
            return;
        }
        this.apply(run, event);
        this.emit();
    }

    private apply(run: RunData, event: ServerEvent): void {
        if (event.type === 'event.progress') {
            run.progress = event.progress;
        } else if (event.type === 'event.frame') {
            run.addFrame(event);
        } else if (event.type === 'event.resync') {
            run.resync();
        } else if (event.type === 'event.done') {
            run.state = event.state;
            run.error = event.error ?? '';
            run.stopReason = event.stop_reason ?? '';
            if (event.state === 'done') run.progress = 1;
            // The stream is incomplete (event.resync, or a frame went missing), or the run failed
            // and its stream may end before what it logged: take the stored result, which exists
            // once the job has ended (a stopped or failed run keeps what it logged).
            if (run.gap || run.state === 'failed') void this.loadStored(run);
        }
    }

    /** Replaces what was streamed for `run` with its stored result; no result leaves it as it is. */
    private async loadStored(run: RunData): Promise<void> {
        const names = run.variables.length > 0 ? run.variables : [...run.columns.keys()];
        if (names.length === 0) return;   // nothing streamed yet; ensure() loads what plots need
        try {
            run.setResults(await this.transport.resultsJson(run.jobId, names));
            this.emit();
        } catch {
            // a failed run may have stored nothing
        }
    }

    private emit(): void { for (const l of this.listeners) l(); }
}

/** A stored run that ended, with no samples yet: ensure() loads those asked for. */
function finishedRun(job: JobInfo): RunData {
    const run = new RunData(job.id, [], runLabel(job));
    run.state = job.state;
    run.progress = 1;
    run.error = job.error;
    run.stopReason = job.stop_reason ?? '';
    return run;
}

/** How plots and the run history name a run: the user's name for it, else "run 12". */
export const runLabel = (job: Pick<JobInfo, 'id' | 'name'>) => job.name || `run ${job.id}`;

/** A run of the history the plots can show: it ended, and the server still has its results. */
export function isChoosable(job: JobInfo): boolean {
    return (job.state === 'done' || job.state === 'failed') && !job.results_dropped;
}

/** Runs whose results the server stores: those that ended well, and failed ones up to the failure. */
function hasStoredResults(run: RunData): boolean {
    return run.state === 'done' || run.state === 'failed';
}

/** The server has no results for the job: none were stored (404) or they were dropped (410). */
function isNoResults(e: unknown): boolean {
    return e instanceof ApiError && (e.status === 404 || e.status === 410);
}
