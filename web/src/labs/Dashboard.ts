// The staff's view of an assignment: one row per student (status, last run, hand-in time,
// late, score, grade), each student's copy (opened read-only in the editor) and hand-ins in
// detail with comments and (teacher) the grade, and an overlay plot of one variable of every
// student's latest run.
import { errorText, h, toast } from '../ui/dom';
import type { Session } from '../app/Session';
import type { Assignment, Check, DashboardRow, LabClass } from './types';
import { STATUS_LABELS } from './types';
import { formatNumber, formatScore, formatTime } from './format';
import { handInDetails } from './HandInDetails';
import { OverlayPlot } from './OverlayPlot';

export interface DashboardPart { element: HTMLElement; dispose(): void }

const COLUMNS = ['Student', 'Status', 'Last run', 'Handed in', 'Late', 'Score', 'Grade', ''];

export function dashboard(session: Session, assignment: Assignment, theClass: LabClass, checks: Check[], teacher: boolean): DashboardPart {
    const labs = session.labs;
    const body = h('tbody');
    const message = h('p', { class: 'form-error', role: 'alert' });
    const open = new Set<number>();   // students whose details are shown

    const detailsRow = (row: DashboardRow) => {
        const cell = h('td', { colspan: COLUMNS.length }, h('p', { class: 'muted' }, 'Loading the hand-ins…'));
        labs.handIns(assignment.id, row.student.id).then((handIns) => {
            cell.replaceChildren(...(handIns.length === 0
                ? [h('p', { class: 'muted' }, `${row.student.username} has not handed in.`)]
                : handIns.map((hi) => handInDetails(session, hi, {
                    canComment: true, canGrade: teacher, archived: theClass.archived, onChanged: () => void refresh(),
                }))));
        }, (e) => cell.replaceChildren(h('p', { class: 'form-error' }, errorText(e))));
        return h('tr', { class: 'details-row', 'data-details-for': row.student.username }, cell);
    };

    const render = (rows: DashboardRow[]) => {
        body.replaceChildren(...rows.flatMap((row) => {
            const shown = open.has(row.student.id);
            const tr = h('tr', { 'data-student': row.student.username, class: shown ? 'expanded' : '' },
                h('td', {}, row.student.username),
                h('td', { class: `status status-${row.status}`, 'data-testid': 'row-status', 'data-status': row.status }, STATUS_LABELS[row.status] ?? row.status),
                h('td', {}, formatTime(row.last_run_at)),
                h('td', {}, formatTime(row.handed_in_at), row.handins > 1 ? h('span', { class: 'muted' }, ` (${row.handins} attempts)`) : null),
                h('td', {}, row.handed_in_at ? (row.late ? h('span', { class: 'badge late-badge' }, 'late') : 'no') : ''),
                h('td', { 'data-testid': 'row-score' }, formatScore(row.score, row.max_score)),
                h('td', { 'data-testid': 'row-grade' }, formatNumber(row.grade)),
                h('td', {}, h('div', { class: 'row-actions' },
                    row.copy_model_id ? h('a', { href: `#/model/${row.copy_model_id}?assignment=${assignment.id}`, class: 'button-link', title: 'Open the student\'s copy (read-only)' }, 'Open copy') : null,
                    row.handins > 0 ? h('button', {
                        'aria-expanded': String(shown),
                        onclick: () => {
                            if (open.has(row.student.id)) open.delete(row.student.id);
                            else open.add(row.student.id);
                            render(rows);
                        },
                    }, shown ? 'Hide hand-ins' : 'Hand-ins') : null)));
            return shown ? [tr, detailsRow(row)] : [tr];
        }));
    };
    const refresh = async () => {
        try {
            const rows = await labs.dashboard(assignment.id);
            rows.sort((a, b) => a.student.username.localeCompare(b.student.username));
            if (rows.length === 0) body.replaceChildren(h('tr', {}, h('td', { colspan: COLUMNS.length, class: 'muted' }, 'No students in the class yet.')));
            else render(rows);
            message.textContent = '';
        } catch (e) {
            message.textContent = errorText(e);
        }
    };
    void refresh();

    // ---- overlay
    const variables = [...new Set(checks.map((c) => c.definition?.variable).filter((v): v is string => !!v))];
    const plot = new OverlayPlot();
    const variable = h('input', { 'aria-label': 'Variable', name: 'overlay-variable', list: `overlay-variables-${assignment.id}`, value: variables[0] ?? '', placeholder: 'Mass#P1#x', class: 'variable-input' });
    const showOverlay = async () => {
        const name = variable.value.trim();
        if (!name) {
            plot.clear('Choose a variable (as the results name it, e.g. Mass#P1#x).');
            return;
        }
        try {
            plot.show(await labs.overlay(assignment.id, name));
        } catch (e) {
            plot.clear(errorText(e));
        }
    };
    const picker = h('form', {
        class: 'toolbar', 'aria-label': 'Overlay variable',
        onsubmit: (e: Event) => { e.preventDefault(); void showOverlay(); },
    }, h('label', {}, 'Variable ', variable),
    h('datalist', { id: `overlay-variables-${assignment.id}` }, ...variables.map((v) => h('option', { value: v }))),
    h('button', { type: 'submit' }, 'Plot'));
    void showOverlay();

    const element = h('div', { class: 'dashboard' },
        h('div', { class: 'toolbar' }, h('button', {
            'data-testid': 'refresh-dashboard',
            onclick: () => { void refresh(); void showOverlay(); toast('Refreshed'); },
        }, 'Refresh')),
        h('table', { class: 'model-table dashboard-table', 'data-testid': 'dashboard-table' },
            h('thead', {}, h('tr', {}, ...COLUMNS.map((c) => h('th', {}, c)))), body),
        message,
        h('h3', {}, 'Overlay of the latest runs'),
        picker, plot.element);
    return { element, dispose: () => plot.dispose() };
}
