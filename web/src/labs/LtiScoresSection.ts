// The staff's view of an assignment's scores on their way to learning platforms' grade books
// (an assignment placed in a Moodle or Canvas course): who, what score, which platform, and
// whether it arrived; pending ones say when the server tries again, failed ones why it gave up.
// The section shows only when there is something to show: an assignment never placed in a
// course has no scores, and a server without the LTI routes answers 404.
import { errorText, h, toast } from '../ui/dom';
import { ApiError } from '../api/ApiError';
import type { LtiScoreInfo } from '../protocol/types';
import type { LabClient } from './LabClient';
import { formatScore, formatTime } from './format';

const COLUMNS = ['Student', 'Score', 'Platform', 'State', 'Created', 'Delivered'];

/** The state with its attempts, the next attempt of a pending score, and the last error. */
function stateCell(s: LtiScoreInfo): HTMLElement {
    const attempts = s.attempts > 0 ? `${s.attempts} attempt${s.attempts === 1 ? '' : 's'}`
        : s.state === 'pending' ? 'not sent yet' : 'not sent';
    return h('td', { 'data-testid': 'lti-score-state', 'data-state': s.state },
        h('span', { class: `badge lti-state lti-state-${s.state}` }, s.state),
        h('span', { class: 'muted' }, ` ${attempts}`),
        s.state === 'pending' && s.next_attempt_at ? h('span', { class: 'muted' }, `, next ${formatTime(s.next_attempt_at)}`) : null,
        s.last_error ? h('div', { class: 'lti-score-error', 'data-testid': 'lti-score-error' }, s.last_error) : null);
}

/** The table of score deliveries, newest first as the server lists them. */
export function ltiScoresTable(scores: LtiScoreInfo[]): HTMLElement {
    return h('table', { class: 'model-table lti-scores-table', 'data-testid': 'lti-scores-table' },
        h('thead', {}, h('tr', {}, ...COLUMNS.map((c) => h('th', {}, c)))),
        h('tbody', {}, ...scores.map((s) => h('tr', { 'data-score': String(s.id) },
            h('td', {}, s.user.username),
            h('td', {}, formatScore(s.score_given, s.score_maximum)),
            h('td', {}, s.platform),
            stateCell(s),
            h('td', {}, formatTime(s.created_at)),
            h('td', {}, formatTime(s.delivered_at))))));
}

/** The section, hidden until a load finds scores; Refresh loads again. */
export function ltiScoresSection(labs: LabClient, assignmentId: number): HTMLElement {
    const body = h('div');
    const message = h('p', { class: 'form-error', role: 'alert' });
    const element = h('section', { class: 'lab-section', 'data-testid': 'lti-scores', hidden: true },
        h('h2', {}, 'Grades sent to learning platforms'),
        h('div', { class: 'toolbar' }, h('button', {
            type: 'button', 'data-testid': 'refresh-lti-scores',
            onclick: async () => { if (await refresh()) toast('Refreshed'); },
        }, 'Refresh')),
        body, message);

    /** Loads the scores; false when the load failed. */
    async function refresh(): Promise<boolean> {
        try {
            const scores = await labs.ltiScores(assignmentId);
            body.replaceChildren(ltiScoresTable(scores));
            message.textContent = '';
            element.hidden = scores.length === 0;
            return true;
        } catch (e) {
            // no LTI routes on this server, or not this user's to see: nothing to show
            if (e instanceof ApiError && (e.status === 404 || e.status === 403)) {
                element.hidden = true;
            } else {
                message.textContent = errorText(e);
                element.hidden = false;
            }
            return false;
        }
    }
    void refresh();
    return element;
}
