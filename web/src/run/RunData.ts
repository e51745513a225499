// Columnar data of one run, filled by event.frame messages (new samples per frame) or by a
// results download; and the alignment of several runs onto one time axis for uPlot.
import type { FrameEvent, JobState, ResultsJson } from '../protocol/types';

export class RunData {
    time: number[] = [];
    readonly columns = new Map<string, number[]>();
    state: JobState = 'queued';
    progress = 0;
    error = '';
    /** Why a component of the model ended the run (SignalStopSimulation): a normal finish. */
    stopReason = '';
    lastSeq = -1;
    /** A frame went missing or the server sent event.resync: the streamed data is incomplete. */
    gap = false;
    /** The server stopped streaming this run (event.resync): its stored result replaces it. */
    resynced = false;

    /**
     * After a reconnect the job is streamed again from sample 0: these many leading samples of
     * the time vector and of each column are ones the run already has, and are dropped.
     */
    private skipTime = 0;
    private readonly skipColumns = new Map<string, number>();

    /** Time span the run covers, when known: plots show all of it while the run fills it. */
    span: [number, number] | null = null;

    /** `label` names the run's curves; the user may rename the run. */
    constructor(readonly jobId: number, readonly variables: string[], public label = `run ${jobId}`) {}

    /**
     * Appends a frame's samples; frames of another job, or after event.resync, are ignored.
     * A frame with `dropped` > 0 holds the samples of the frames merged into it: no gap.
     */
    addFrame(frame: FrameEvent): void {
        if (frame.job_id !== this.jobId || this.resynced) return;
        if (frame.seq !== this.lastSeq + 1) this.gap = true;
        this.lastSeq = frame.seq;
        this.skipTime = appendAfter(this.time, frame.time, this.skipTime);
        for (const [name, values] of Object.entries(frame.variables)) {
            let column = this.columns.get(name);
            if (!column) {
                column = [];
                this.columns.set(name, column);
            }
            const skip = this.skipColumns.get(name) ?? 0;
            if (skip > 0) this.skipColumns.set(name, appendAfter(column, values, skip));
            else for (const x of values) column.push(x);
        }
    }

    /**
     * The job is subscribed again (a new socket): its frames start over at seq 0 and sample 0.
     * The samples the run holds stay (plots keep them); as many leading samples of the new
     * stream, per column, are dropped, so the run goes on exactly where it was.
     */
    restartStream(): void {
        this.lastSeq = -1;
        this.skipTime = this.time.length;
        this.skipColumns.clear();
        for (const [name, column] of this.columns) this.skipColumns.set(name, column.length);
    }

    /** event.resync: no more frames come; what was streamed stays until the stored result replaces it. */
    resync(): void {
        this.resynced = true;
        this.gap = true;
    }

    /** Replaces the streamed columns with the stored result (exact). */
    setResults(results: ResultsJson): void {
        this.time = [...results.time];
        for (const v of results.variables) this.columns.set(v.name, [...v.data]);
        this.gap = false;
    }

    has(name: string): boolean { return this.columns.has(name); }

    get finished(): boolean { return this.state !== 'queued' && this.state !== 'running'; }
}

/** Appends `values` to `target` after dropping the first `skip` of them; returns what is left to skip. */
function appendAfter(target: number[], values: ArrayLike<number>, skip: number): number {
    if (skip >= values.length) return skip - values.length;
    for (let i = skip; i < values.length; ++i) target.push(values[i]);
    return 0;
}

export interface SeriesSource { time: number[]; data: number[] }

/**
 * Puts series with possibly different time vectors on one sorted x axis (uPlot's AlignedData);
 * a series has null where it has no sample.
 */
export function alignSeries(series: SeriesSource[]): [number[], ...(number | null)[][]] {
    if (series.length === 0) return [[]];
    const first = series[0].time;
    const same = series.every((s) => s.time === first || sameArray(s.time, first));
    if (same) {
        const n = first.length;
        return [first.slice(0, n), ...series.map((s) => padTo(s.data, n))];
    }
    const xs = [...new Set(series.flatMap((s) => s.time))].sort((a, b) => a - b);
    const index = new Map(xs.map((x, i) => [x, i]));
    const columns = series.map((s) => {
        const column: (number | null)[] = new Array(xs.length).fill(null);
        const n = Math.min(s.time.length, s.data.length);
        for (let i = 0; i < n; ++i) column[index.get(s.time[i])!] = s.data[i];
        return column;
    });
    return [xs, ...columns];
}

function sameArray(a: number[], b: number[]): boolean {
    if (a.length !== b.length) return false;
    for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) return false;
    return true;
}

// a column still filling up during a run is shorter than its time vector
function padTo(data: number[], n: number): (number | null)[] {
    if (data.length >= n) return data.slice(0, n);
    return [...data, ...new Array<null>(n - data.length).fill(null)];
}

/** CSV of aligned series, like the server's: header then "%.17g"-like rows (JS shortest form). */
export function toCsv(names: string[], aligned: [number[], ...(number | null)[][]], xName = 'time'): string {
    const [xs, ...cols] = aligned;
    const lines = [[xName, ...names].join(',')];
    for (let i = 0; i < xs.length; ++i) {
        lines.push([xs[i], ...cols.map((c) => (c[i] === null || c[i] === undefined ? '' : String(c[i])))].join(','));
    }
    return lines.join('\n') + '\n';
}
