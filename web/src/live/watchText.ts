// What the live watch page (WatchView.ts) shows in words, and which streamed variables it plots.
import type { LiveStatus } from './LiveSession';
import { formatTime } from './liveErrors';

/** The watched session's state and model time, e.g. "Live · t = 1.25 s". */
export function watchStatusText(status: LiveStatus): string {
    const time = `t = ${formatTime(status.modelTime)} s`;
    switch (status.phase) {
    case 'starting': return 'Joining the live session…';
    case 'running': return `Live · ${time}`;
    case 'paused': return `Paused by its owner · ${time}`;
    case 'stopped': return `Ended · ${time}`;
    default: return '';
    }
}

/**
 * What the plots show: the model's sink variables the session streams (what ▶ Run would
 * plot), else the first streamed variable; a watcher adds no variables (they are the session's).
 */
export function watchedPlotVariables(sinks: string[], streamed: string[]): string[] {
    const shown = sinks.filter((name) => streamed.includes(name));
    return shown.length > 0 ? shown : streamed.slice(0, 1);
}
