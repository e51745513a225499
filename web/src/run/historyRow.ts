// The words of a run history row: when the run was, what became of it, and what it simulated.
import type { JobInfo } from '../protocol/types';

const MONTHS = ['Jan', 'Feb', 'Mar', 'Apr', 'May', 'Jun', 'Jul', 'Aug', 'Sep', 'Oct', 'Nov', 'Dec'];
const two = (n: number) => String(n).padStart(2, '0');

/**
 * When a run was (unix seconds), as a glance needs it: "just now", "5 min ago", "14:05" today,
 * "12 Mar 14:05" this year, else "2023-03-12"; in local time.
 */
export function whenText(at: number, now: Date): string {
    const then = new Date(at * 1000);
    const ago = now.getTime() / 1000 - at;
    if (ago < 60) return 'just now';
    if (ago < 3600) return `${Math.floor(ago / 60)} min ago`;
    const clock = `${two(then.getHours())}:${two(then.getMinutes())}`;
    if (then.toDateString() === now.toDateString()) return clock;
    if (then.getFullYear() === now.getFullYear()) return `${then.getDate()} ${MONTHS[then.getMonth()]} ${clock}`;
    return `${then.getFullYear()}-${two(then.getMonth() + 1)}-${two(then.getDate())}`;
}

/** What became of a run: "done", "ended by model: …", "failed: …", "cancelled", "running". */
export function stateText(job: Pick<JobInfo, 'state' | 'error' | 'stop_reason'>): string {
    if (job.state === 'done') return job.stop_reason ? `ended by model: ${job.stop_reason}` : 'done';
    if (job.state === 'failed') return job.error ? `failed: ${job.error}` : 'failed';
    return job.state;
}

/** What the run simulated: "0–3 s, 30000 steps" (steps once known). */
export function spanText(job: Pick<JobInfo, 'settings' | 'steps'>): string {
    const { start, stop } = job.settings;
    return `${start}–${stop} s${job.steps > 0 ? `, ${job.steps} steps` : ''}`;
}
