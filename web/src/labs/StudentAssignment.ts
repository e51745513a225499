// A student's side of an assignment: the status, the own copy (open it in the editor, reset it
// to a newer template), the checks, pretests run on the server, handing in and the hand-ins
// with their checks and the staff's comments.
import { errorText, h, toast } from '../ui/dom';
import { ApiError } from '../api/ApiError';
import type { Session } from '../app/Session';
import type { Assignment, Check, HandIn, LabClass } from './types';
import { STATUS_LABELS } from './types';
import { formatNumber, formatScore } from './format';
import { handInDetails, handInSummary, outcomesTable } from './HandInDetails';
import { section } from './LabPage';

/** What a check asks, in words (students see the pretests' definitions only). */
export function checkText(c: Check): string {
    const d = c.definition;
    if (!d) return c.pretest ? '' : 'checked at hand-in';
    if (d.kind === 'curve') return `${d.variable} follows the reference within ${formatNumber((d.tolerance ?? 0.01) * 100)} %`;
    const bounds = d.min !== undefined && d.max !== undefined ? `between ${formatNumber(d.min)} and ${formatNumber(d.max)}`
        : d.min !== undefined ? `at least ${formatNumber(d.min)}` : `at most ${formatNumber(d.max)}`;
    return `${d.measure.replace('_', ' ')} of ${d.variable} ${bounds}`;
}

function refusal(e: unknown): string {
    if (e instanceof ApiError) {
        if (e.code === 'archived') return `The class is archived: ${e.message}`;
        if (e.code === 'deadline_passed') return `The deadline has passed: ${e.message}`;
        if (e.code === 'locked') return `Not allowed in this assignment: ${e.message}`;
    }
    return errorText(e);
}

export function studentAssignment(session: Session, assignment: Assignment, theClass: LabClass, checks: Check[],
    rerender: () => void): HTMLElement {
    const labs = session.labs;
    const status = assignment.status ?? 'not_opened';
    const copy = assignment.copy ?? null;
    const message = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'student-error' });
    const fail = (e: unknown) => { message.textContent = refusal(e); };

    const openButton = h('button', {
        class: 'primary', 'data-testid': 'open-copy',
        onclick: async () => {
            message.textContent = '';
            openButton.disabled = true;
            try {
                const opened = await labs.open(assignment.id);
                location.hash = `#/model/${opened.model_id}?assignment=${assignment.id}`;
            } catch (e) {
                fail(e);
                openButton.disabled = false;
            }
        },
    }, copy ? 'Open my copy' : 'Start: get my copy');
    const resetButton = copy?.outdated ? h('button', {
        'data-testid': 'reset-copy',
        onclick: async () => {
            if (!confirm('Replace your copy with the new template? Your changes to the copy are lost.')) return;
            try {
                await labs.reset(assignment.id);
                toast('Your copy now has the current template');
                rerender();
            } catch (e) {
                fail(e);
            }
        },
    }, 'Reset to template') : null;
    const work = h('div', { class: 'student-work' },
        h('p', {}, 'Status: ', h('strong', { class: `status status-${status}`, 'data-testid': 'student-status', 'data-status': status }, STATUS_LABELS[status]),
            copy ? h('span', { class: 'muted' }, ` · your copy is of template version ${copy.template_version}`) : null),
        copy?.outdated ? h('p', { class: 'notice', 'data-testid': 'outdated' },
            `Your teacher published a new template (version ${assignment.template_version}); your copy is of version ${copy.template_version} and keeps your changes. Reset it to get the new template.`) : null,
        h('div', { class: 'toolbar' }, openButton, resetButton),
        h('p', { class: 'muted' }, 'Work in your copy in the editor: change what the assignment allows, save, and run it. Pretests and hand-ins run your copy as saved on the server.'),
        message);

    // ---- checks and pretests
    const pretests = checks.filter((c) => c.pretest);
    const checkList = checks.length === 0 ? h('p', { class: 'muted' }, 'No checks yet.') : h('table', { class: 'model-table', 'data-testid': 'check-list' },
        h('thead', {}, h('tr', {}, h('th', {}, 'Check'), h('th', {}, 'Points'), h('th', {}, 'When'), h('th', {}, 'What'))),
        h('tbody', {}, ...checks.map((c) => h('tr', {}, h('td', {}, c.name), h('td', {}, formatNumber(c.points)),
            h('td', {}, c.pretest ? 'pretest and hand-in' : 'hand-in'), h('td', {}, checkText(c))))));
    const pretestResult = h('div', { class: 'pretest-result', 'data-testid': 'pretest-result' });
    const pretestButton = h('button', {
        'data-testid': 'run-pretests', disabled: !copy || pretests.length === 0,
        title: !copy ? 'Get your copy first' : pretests.length === 0 ? 'This assignment has no pretests' : 'Run your saved copy and judge it by the pretests',
        onclick: async () => {
            message.textContent = '';
            pretestButton.disabled = true;
            pretestResult.replaceChildren(h('p', { class: 'muted' }, 'Running your copy…'));
            try {
                const result = await labs.pretest(assignment.id, (state) => {
                    pretestResult.replaceChildren(h('p', { class: 'muted', 'data-testid': 'pretest-waiting' },
                        state === 'queued' ? 'Your copy waits for a free worker…' : 'Your copy is still running…'));
                });
                pretestResult.replaceChildren(
                    h('p', {}, 'Pretests: ', h('strong', { 'data-testid': 'pretest-score' }, formatScore(result.score, result.max_score)),
                        ` · ${result.checks.filter((c) => c.passed).length} of ${result.checks.length} passed`),
                    outcomesTable(result.checks, 'pretest-results'));
            } catch (e) {
                pretestResult.replaceChildren();
                fail(e);
            } finally {
                pretestButton.disabled = false;
            }
        },
    }, 'Run pretests');

    // ---- hand in
    const history = h('div', { class: 'handin-history', 'data-testid': 'handin-history' }, h('p', { class: 'muted' }, 'Loading…'));
    const showHistory = (handIns: HandIn[]) => history.replaceChildren(...(handIns.length === 0
        ? [h('p', { class: 'muted' }, 'Not handed in yet.')]
        : handIns.map((hi, i) => {
            const details = h('details', { open: i === 0, class: 'handin-details' },
                h('summary', {}, handInSummary(hi)),
                handInDetails(session, hi, { canComment: false, canGrade: false, archived: theClass.archived, header: false }));
            return details;
        })));
    labs.handIns(assignment.id).then(showHistory, (e) => history.replaceChildren(h('p', { class: 'form-error' }, errorText(e))));
    const deadlinePassed = assignment.due_at > 0 && assignment.due_at < Date.now() / 1000;
    const handInButton = h('button', {
        class: 'primary', 'data-testid': 'hand-in', disabled: !copy || theClass.archived,
        onclick: async () => {
            message.textContent = '';
            handInButton.disabled = true;
            handInButton.textContent = 'Handing in…';
            try {
                const handIn = await labs.handIn(assignment.id);
                toast(`Handed in (attempt ${handIn.attempt}): ${formatScore(handIn.score, handIn.max_score)}`);
                rerender();
            } catch (e) {
                fail(e);
                handInButton.disabled = false;
                handInButton.textContent = 'Hand in';
            }
        },
    }, 'Hand in');

    return h('div', { class: 'student-assignment' },
        section('Your work', 'student-work', work),
        section('Checks', 'student-checks', checkList, h('div', { class: 'toolbar' }, pretestButton), pretestResult),
        section('Hand in', 'student-handin',
            h('p', { class: 'muted' }, deadlinePassed
                ? 'The deadline has passed: a first hand-in is still taken (marked late), no further one.'
                : 'Handing in freezes your saved copy, runs it and judges it by every check. You may hand in again until the deadline; every attempt is kept.'),
            h('div', { class: 'toolbar' }, handInButton),
            history));
}
