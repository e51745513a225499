// A hand-in in detail: its attempt, time, late flag, score and grade, the outcome of every
// check, and the comments on it; staff add comments, the teacher sets the grade.
import { errorText, h, toast } from '../ui/dom';
import type { Session } from '../app/Session';
import type { CheckOutcome, HandIn, HandInComment } from './types';
import { formatNumber, formatScore, formatTime } from './format';

/** The outcomes of checks: name, passed, points, value or deviation, message. */
export function outcomesTable(outcomes: CheckOutcome[], testId?: string): HTMLElement {
    if (outcomes.length === 0) return h('p', { class: 'muted', 'data-testid': testId }, 'No checks.');
    return h('table', { class: 'model-table outcomes', 'data-testid': testId },
        h('thead', {}, h('tr', {}, h('th', {}, 'Check'), h('th', {}, 'Result'), h('th', {}, 'Points'),
            h('th', {}, 'Value / deviation'), h('th', {}, 'Message'))),
        h('tbody', {}, ...outcomes.map((o) => h('tr', { class: o.passed ? 'passed' : 'failed', 'data-check': o.name },
            h('td', {}, o.name, o.pretest ? h('span', { class: 'badge pretest-badge' }, 'pretest') : null),
            h('td', { class: 'outcome', 'data-passed': String(o.passed) }, o.passed ? '✓ passed' : '✗ failed'),
            h('td', {}, `${formatNumber(o.awarded)} / ${formatNumber(o.points)}`),
            h('td', {}, valueText(o)),
            h('td', { class: 'message' }, o.message || '')))));
}

function valueText(o: CheckOutcome): string {
    const parts: string[] = [];
    if (o.value !== undefined && o.value !== null) parts.push(`value ${formatNumber(o.value)}`);
    if (o.deviation !== undefined && o.deviation !== null) {
        // rounding noise of an equal run (1e-16) reads as what it is
        const tiny = Math.abs(o.deviation) < 1e-9;
        parts.push(tiny ? 'deviation ≈ 0 %' : `deviation ${formatNumber(o.deviation * 100, 3)} %`);
        if (!tiny && o.worst_time !== undefined && o.worst_time !== null) parts.push(`at t = ${formatNumber(o.worst_time)} s`);
    }
    return parts.join(', ') || '—';
}

export interface HandInOptions {
    /** staff: may comment */
    canComment: boolean;
    /** the teacher: may grade */
    canGrade: boolean;
    /** archived class: read-only */
    archived: boolean;
    /** false: the caller shows the summary line (e.g. as a <details> summary) */
    header?: boolean;
    onChanged?: () => void;
}

/** One line about a hand-in. */
export function handInSummary(handIn: HandIn): HTMLElement {
    return h('span', { class: 'handin-summary' },
        h('strong', {}, `Attempt ${handIn.attempt}`), ` · ${formatTime(handIn.handed_in_at)} · `,
        handIn.late ? h('span', { class: 'badge late-badge', 'data-testid': 'late' }, 'late') : null,
        handIn.late ? ' · ' : null,
        h('span', { 'data-testid': 'handin-score' }, `score ${formatScore(handIn.score, handIn.max_score)}`),
        handIn.grade !== null && handIn.grade !== undefined ? h('span', { 'data-testid': 'handin-grade' }, ` · grade ${formatNumber(handIn.grade)}`) : null);
}

export function handInDetails(session: Session, handIn: HandIn, options: HandInOptions): HTMLElement {
    const labs = session.labs;
    const checks = h('div', { class: 'handin-checks' });
    const showChecks = (outcomes: CheckOutcome[]) => checks.replaceChildren(outcomesTable(outcomes, 'handin-checks'));
    if (handIn.checks) showChecks(handIn.checks);
    else {
        checks.append(h('p', { class: 'muted' }, 'Loading the checks…'));
        labs.getHandIn(handIn.id).then((full) => showChecks(full.checks ?? []),
            (e) => checks.replaceChildren(h('p', { class: 'form-error' }, errorText(e))));
    }

    const commentList = h('ul', { class: 'comments', 'data-testid': 'comments' });
    const showComments = (comments: HandInComment[]) => commentList.replaceChildren(...(comments.length === 0
        ? [h('li', { class: 'muted no-comments' }, 'No comments.')]
        : comments.map((c) => h('li', { class: 'comment', 'data-comment-id': String(c.id) },
            h('div', { class: 'comment-head' }, h('strong', {}, c.author.username), h('span', { class: 'muted' }, ` · ${formatTime(c.created_at)}`)),
            // plain text: a comment is shown as written, never as HTML
            h('div', { class: 'comment-text' }, c.text)))));
    const loadComments = () => labs.comments(handIn.id).then(showComments,
        (e) => commentList.replaceChildren(h('li', { class: 'form-error' }, errorText(e))));
    void loadComments();

    const writable = !options.archived;
    const commentText = h('textarea', { 'aria-label': 'Comment', rows: 2, placeholder: 'A comment for the student' });
    const commentForm = options.canComment && writable ? h('form', {
        class: 'comment-form', 'aria-label': 'Add a comment',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            const text = commentText.value.trim();
            if (!text) return;
            try {
                await labs.addComment(handIn.id, text);
                commentText.value = '';
                await loadComments();
            } catch (err) {
                toast(errorText(err), 'error');
            }
        },
    }, commentText, h('button', { type: 'submit' }, 'Comment')) : null;

    const grade = h('input', { 'aria-label': 'Grade', inputmode: 'decimal', class: 'num', value: handIn.grade ?? '', placeholder: formatNumber(handIn.score) });
    const gradeForm = options.canGrade && writable ? h('form', {
        class: 'grade-form', 'aria-label': 'Grade the hand-in',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            const text = grade.value.trim();
            const value = text === '' ? null : Number(text);
            if (value !== null && !Number.isFinite(value)) {
                toast('The grade must be a number (empty: clear it).', 'error');
                return;
            }
            try {
                await labs.setGrade(handIn.id, value);
                toast(value === null ? 'Grade cleared' : `Graded ${formatNumber(value)}`);
                options.onChanged?.();
            } catch (err) {
                toast(errorText(err), 'error');
            }
        },
    }, h('label', {}, 'Grade ', grade), h('button', { type: 'submit' }, 'Set grade'),
    h('span', { class: 'muted' }, ' (empty clears it; the gradebook takes the grade over the score)')) : null;

    return h('article', { class: 'handin', 'data-handin-id': String(handIn.id), 'data-attempt': String(handIn.attempt) },
        options.header === false ? null : h('header', {}, handInSummary(handIn)),
        checks,
        gradeForm,
        h('div', { class: 'comment-box' }, h('h4', {}, 'Comments'), commentList, commentForm));
}
