// What went wrong with a live session, in words that name the thing to do: the server's error
// codes (protocol/README.md) read as a Hopsan user needs them.
import { ApiError } from '../api/ApiError';
import { errorText } from '../ui/dom';
import type { LiveStateEvent } from '../protocol/types';

/** The message for a failed live request; `what` is what was asked ("Go live", "Set Step.y_A"). */
export function liveErrorText(what: string, e: unknown): string {
    if (!(e instanceof ApiError)) return `${what}: ${errorText(e)}`;
    switch (e.code) {
    case 'restart_required':
        return `${what}: ${e.message}. It cannot change while the model runs: stop, change the parameter, and go live again.`;
    case 'rate_limited':
        return `${what}: you already run as many live sessions as the server allows per user (${e.message}). Stop one (in another tab or window) and try again.`;
    case 'busy':
        return `${what}: the server runs as many live sessions as it can (${e.message}). Try again in a moment.`;
    case 'invalid_parameter':
    case 'unknown_parameter':
        return `${what}: ${e.message}. The model has no such value to change while it runs.`;
    case 'not_found':
        return `${what}: the live session has ended on the server.`;
    case 'not_connected':
    case 'connection_lost':
        return `${what}: the connection to the server was lost; the live session has ended.`;
    default:
        return `${what}: ${e.message}`;
    }
}

/** Why a session stopped, from its last event.live.state. */
export function stoppedText(event: Pick<LiveStateEvent, 'reason' | 'message' | 'model_time'>): string {
    const detail = event.message ? ` (${event.message})` : '';
    switch (event.reason) {
    case 'finished': return `Stopped at the stop time, t = ${formatTime(event.model_time)} s.`;
    case 'idle_timeout': return `Stopped: nothing was sent to the session for too long${detail}. Go live again to go on.`;
    case 'failed': return `The simulation failed${detail}.`;
    case 'shutdown': return 'Stopped: the server is shutting down.';
    case 'closed': return 'Stopped: the window that started the session was closed.';
    case 'unshared': return 'The teacher stopped sharing the live session with your class.';
    case 'requested': return `Stopped at t = ${formatTime(event.model_time)} s.`;
    default: return `Stopped${detail}.`;
    }
}

export function formatTime(t: number): string {
    return Number.isFinite(t) ? String(Number(t.toPrecision(4))) : '?';
}
