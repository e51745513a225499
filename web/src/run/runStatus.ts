// The run status line: what became of the current run, in words, so that a run a component
// ended as designed reads as done with its reason, and a failed one names its error.
import type { RunData } from './RunData';

/** The status text of `run` (running or ended). */
export function runStatusText(run: RunData): string {
    if (!run.finished) return `Job ${run.jobId}: running ${Math.round(run.progress * 100)}%`;
    const reason = run.state === 'done' ? run.stopReason : run.error;
    return `Job ${run.jobId}: ${run.state}${reason ? ` — ${reason}` : ''}`;
}
