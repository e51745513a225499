// A plot window steps through the model's runs (Hopsan's plot generations) in the order they
// were run: it shows one run, with the run before it to compare, and follows the newest run
// unless the user stepped back or chose an older one.

/** How many runs of a model a window can step through: as many as the server keeps by default. */
export const MAX_GENERATIONS = 20;

/** A run as the stepping sees it: its job id, which the server gives out in the order runs start. */
export interface Generation { readonly jobId: number }

/**
 * `runs` (oldest first) with `run` among them in its place in time, whenever it was loaded or
 * chosen; beyond MAX_GENERATIONS the oldest of the others go.
 */
export function withGeneration<T extends Generation>(runs: readonly T[], run: T): T[] {
    const others = runs.filter((r) => r !== run && r.jobId !== run.jobId);
    const kept = others.slice(Math.max(0, others.length + 1 - MAX_GENERATIONS));
    return [...kept, run].sort((a, b) => a.jobId - b.jobId);
}

/**
 * The run a window shows and the one before it. `shown` is a job id the user stepped to, or
 * null for the newest run; a run no longer listed also falls back to the newest.
 */
export function shownRuns<T extends Generation>(runs: readonly T[], shown: number | null): { run: T | null; before: T | null } {
    const found = shown === null ? -1 : runs.findIndex((r) => r.jobId === shown);
    const i = found >= 0 ? found : runs.length - 1;
    return { run: runs[i] ?? null, before: runs[i - 1] ?? null };
}

/**
 * Steps `by` runs from the shown one (-1: the one before), stopping at the oldest and the
 * newest. Reaching the newest gives null, so the window follows the runs that come after.
 */
export function stepGeneration(runs: readonly Generation[], shown: number | null, by: number): number | null {
    if (runs.length === 0) return null;
    const { run } = shownRuns(runs, shown);
    const i = Math.min(Math.max(runs.indexOf(run!) + by, 0), runs.length - 1);
    return i === runs.length - 1 ? null : runs[i].jobId;
}

/**
 * The two runs a difference curve sets against each other by default: the shown run minus the
 * one before it, or minus the one after it when it is the oldest; null with fewer than two runs.
 */
export function differencePair<T extends Generation>(runs: readonly T[], shown: number | null): { a: T; b: T } | null {
    const { run, before } = shownRuns(runs, shown);
    const b = before ?? runs[runs.indexOf(run!) + 1];
    return run && b ? { a: run, b } : null;
}

/** "run 12 (2 of 3)": which of the runs a window shows, and its place in time. */
export function generationText(runs: readonly (Generation & { label: string })[], shown: number | null): string {
    const { run } = shownRuns(runs, shown);
    return run ? `${run.label} (${runs.indexOf(run) + 1} of ${runs.length})` : '';
}
