// An assignment's page: title, times, what students may change and the instructions
// (Markdown); below, a student's own work (StudentAssignment) or the staff's dashboard, the
// scores sent to learning platforms (LtiScoresSection) and the checks (Dashboard,
// ChecksEditor); the teacher also changes or deletes the assignment here.
import { errorText, h, toast } from '../ui/dom';
import type { Session } from '../app/Session';
import type { Assignment, Check, LabClass } from './types';
import { isStaff, isTeacher } from './types';
import { formatNumber, formatTime } from './format';
import { markdownBlock } from './markdown';
import { errorPage, noCleanup, section, type LabPage } from './LabPage';
import { studentAssignment } from './StudentAssignment';
import { dashboard } from './Dashboard';
import { checksEditor } from './ChecksEditor';
import { assignmentForm } from './AssignmentForm';
import { assignmentWarnings } from './AssignmentWarnings';
import { ltiScoresSection } from './LtiScoresSection';

/** What students may change, in words. */
export function allowedText(a: Assignment): string {
    if (a.edit_mode === 'free') return 'Students may change anything in their copy.';
    if (a.parameters.length === 0) return 'Students may change nothing in their copy.';
    const bounds = (p: Assignment['parameters'][number]) =>
        p.min !== undefined && p.max !== undefined ? ` (${formatNumber(p.min)} … ${formatNumber(p.max)})`
            : p.min !== undefined ? ` (≥ ${formatNumber(p.min)})` : p.max !== undefined ? ` (≤ ${formatNumber(p.max)})` : '';
    return `Students may change only: ${a.parameters.map((p) => `${p.name}${bounds(p)}`).join(', ')}.`;
}

export async function renderAssignment(root: HTMLElement, session: Session, assignmentId: number): Promise<LabPage> {
    // a change on the page shows it again: the page the router holds stops whichever is shown
    let shown: LabPage = noCleanup;
    let left = false;
    const show = async () => {
        const next = await showAssignment(root, session, assignmentId, () => void show());
        shown.dispose();
        shown = next;
        if (left) next.dispose();
    };
    await show();
    return { dispose: () => { left = true; shown.dispose(); } };
}

async function showAssignment(root: HTMLElement, session: Session, assignmentId: number, rerender: () => void): Promise<LabPage> {
    const labs = session.labs;
    root.replaceChildren(h('main', { class: 'loading' }, h('p', { class: 'muted' }, 'Opening assignment…')));
    let assignment: Assignment;
    let theClass: LabClass;
    let checks: Check[];
    try {
        assignment = await labs.getAssignment(assignmentId);
        [theClass, checks] = await Promise.all([labs.getClass(assignment.class_id), labs.getChecks(assignmentId)]);
    } catch (e) {
        root.replaceChildren(errorPage('Cannot open the assignment', errorText(e), { href: '#/classes', label: 'Back to the classes' }));
        return noCleanup;
    }
    const staff = isStaff(theClass.role, session.user?.role);
    const teacher = isTeacher(theClass.role, session.user?.role);
    const now = Date.now() / 1000;

    const header = h('div', { class: 'lab-title' },
        h('h1', { 'data-testid': 'assignment-title' }, assignment.title),
        theClass.archived ? h('span', { class: 'badge' }, 'archived: read-only') : null,
        assignment.opens_at > now ? h('span', { class: 'badge' }, 'not open yet') : null);
    const meta = h('p', { class: 'assignment-meta muted' },
        `Opens ${formatTime(assignment.opens_at)} · `,
        assignment.due_at ? h('span', { class: assignment.due_at < now ? 'overdue' : '' }, `due ${formatTime(assignment.due_at)}`) : 'no deadline',
        ` · ${allowedText(assignment)}`);

    const instructions = section('Instructions', 'instructions-section',
        assignment.instructions.trim() ? markdownBlock(assignment.instructions, { 'data-testid': 'instructions' })
            : h('p', { class: 'muted', 'data-testid': 'instructions' }, 'No instructions.'));

    let page: LabPage = noCleanup;
    const parts: (HTMLElement | null)[] = [];
    if (staff) {
        const board = dashboard(session, assignment, theClass, checks, teacher);
        page = board;
        parts.push(section('Students', 'dashboard', board.element));
        parts.push(ltiScoresSection(labs, assignmentId));
        parts.push(section('Checks', 'checks', checksEditor({
            checks, editable: teacher && !theClass.archived, hasSolution: assignment.has_solution,
            variables: [...new Set(checks.map((c) => c.definition?.variable).filter((v): v is string => !!v))],
            save: async (next) => {
                await labs.putChecks(assignmentId, next);
                rerender();
            },
        })));
        if (teacher && !theClass.archived) parts.push(teacherTools(session, assignment, rerender));
    } else {
        parts.push(studentAssignment(session, assignment, theClass, checks, rerender));
    }

    root.replaceChildren(h('main', { class: 'model-list-page lab-page assignment-page', 'data-testid': 'assignment-page' },
        h('a', { href: `#/class/${theClass.id}`, class: 'back' }, `← ${theClass.name}`),
        header, meta, teacher ? assignmentWarnings(assignment) : null, instructions, ...parts));
    return page;
}

function teacherTools(session: Session, assignment: Assignment, rerender: () => void): HTMLElement {
    const slot = h('div', { class: 'form-slot' });
    return section('Change the assignment', 'assignment-tools',
        h('div', { class: 'toolbar' },
            h('button', {
                onclick: async () => {
                    if (slot.firstChild) { slot.replaceChildren(); return; }
                    try {
                        const models = await session.rest.listModels();
                        slot.replaceChildren(assignmentForm({
                            models, initial: assignment, submitLabel: 'Save changes',
                            onCancel: () => slot.replaceChildren(),
                            onSubmit: async (input) => {
                                await session.labs.updateAssignment(assignment.id, input);
                                toast('Assignment saved');
                                rerender();
                            },
                            loadModel: (id) => session.rest.getModel(id).then((m) => m.model),
                        }));
                    } catch (e) {
                        toast(errorText(e), 'error');
                    }
                },
            }, 'Edit assignment'),
            h('button', {
                class: 'danger',
                onclick: async () => {
                    if (!confirm(`Delete "${assignment.title}" with every hand-in? The students' copies stay theirs.`)) return;
                    try {
                        await session.labs.deleteAssignment(assignment.id);
                        location.hash = `#/class/${assignment.class_id}`;
                    } catch (e) {
                        toast(errorText(e), 'error');
                    }
                },
            }, 'Delete assignment')),
        slot);
}
