// A class page's "Live now": the live sessions its teacher shares with the class
// (docs/live-sessions.md, "In a lab"), each with Watch (the read-only watch page). Asked again
// every few seconds, so a session shared or ended while the page is open shows.
import { h } from '../ui/dom';
import type { LabClient } from './LabClient';
import type { SharedLiveSession } from './types';
import { section } from './LabPage';

const REFRESH_MS = 3000;

export function liveNowSection(labs: LabClient, classId: number): { element: HTMLElement; dispose(): void } {
    const list = h('div', { 'data-testid': 'live-now-list' });
    const show = (sessions: SharedLiveSession[]) => list.replaceChildren(sessions.length === 0
        ? h('p', { class: 'muted' }, 'Nothing is live now.')
        : h('ul', { class: 'live-now' }, ...sessions.map((s) => h('li', { dataset: { sessionId: String(s.session_id) } },
            `${s.teacher.username} is live with ${s.model_name} `,
            h('a', { href: `#/watch/${s.session_id}?class=${classId}`, class: 'button', 'data-testid': 'watch-live' }, 'Watch')))));
    let disposed = false;
    const refresh = () => labs.sharedLiveSessions(classId).then((sessions) => { if (!disposed) show(sessions); }, () => undefined);
    void refresh();
    const dispose = () => {
        disposed = true;
        clearInterval(timer);
    };
    // (a page drawn again after a change replaces this one without disposing it)
    const timer = setInterval(() => (list.isConnected ? void refresh() : dispose()), REFRESH_MS);
    return { element: section('Live now', 'live-now', list), dispose };
}
