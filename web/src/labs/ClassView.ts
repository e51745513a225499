// A class's page: its assignments (students: the open ones with their status), and for the
// staff its members; the teacher also sees the join code, adds and removes members, imports
// accounts, archives the class, sees the gradebook (and exports it) and creates assignments.
import { downloadText, errorText, h, toast } from '../ui/dom';
import type { Session } from '../app/Session';
import type { Assignment, ClassMember, ClassRole, LabClass } from './types';
import { isStaff, isTeacher, STATUS_LABELS } from './types';
import { formatTime } from './format';
import { errorPage, noCleanup, section, type LabPage } from './LabPage';
import { assignmentForm } from './AssignmentForm';
import { gradebookTable } from './GradebookTable';
import { liveNowSection } from './LiveNowSection';

const ROLES: ClassRole[] = ['student', 'assistant', 'teacher'];

export async function renderClass(root: HTMLElement, session: Session, classId: number): Promise<LabPage> {
    const labs = session.labs;
    root.replaceChildren(h('main', { class: 'loading' }, h('p', { class: 'muted' }, 'Opening class…')));
    let theClass: LabClass;
    let assignments: Assignment[];
    try {
        [theClass, assignments] = await Promise.all([labs.getClass(classId), labs.listAssignments(classId)]);
    } catch (e) {
        root.replaceChildren(errorPage('Cannot open the class', errorText(e), { href: '#/classes', label: 'Back to the classes' }));
        return noCleanup;
    }
    const staff = isStaff(theClass.role, session.user?.role);
    const teacher = isTeacher(theClass.role, session.user?.role);
    const rerender = () => void renderClass(root, session, classId);

    // ---- assignments
    const assignmentRows = assignments.map((a) => h('tr', { dataset: { assignmentId: String(a.id) } },
        h('td', {}, h('a', { href: `#/assignment/${a.id}`, class: 'assignment-link' }, a.title)),
        h('td', {}, formatTime(a.opens_at)),
        h('td', {}, a.due_at ? formatTime(a.due_at) : 'none'),
        staff
            ? h('td', {}, a.edit_mode === 'parameters' ? `parameters: ${a.parameters.map((p) => p.name).join(', ')}` : 'free')
            : h('td', { class: `status status-${a.status ?? 'not_opened'}`, 'data-testid': 'assignment-status' }, STATUS_LABELS[a.status ?? 'not_opened'])));
    const assignmentTable = assignments.length === 0
        ? h('p', { class: 'muted' }, staff ? 'No assignments yet.' : 'No open assignments yet.')
        : h('table', { class: 'model-table', 'data-testid': 'assignments-table' },
            h('thead', {}, h('tr', {}, h('th', {}, 'Assignment'), h('th', {}, 'Opens'), h('th', {}, 'Due'), h('th', {}, staff ? 'Students may change' : 'Status'))),
            h('tbody', {}, ...assignmentRows));

    const formSlot = h('div', { class: 'form-slot' });
    const newAssignment = teacher && !theClass.archived ? h('button', {
        class: 'primary', 'data-testid': 'new-assignment',
        onclick: async () => {
            if (formSlot.firstChild) { formSlot.replaceChildren(); return; }
            try {
                const models = await session.rest.listModels();
                formSlot.replaceChildren(assignmentForm({
                    models, submitLabel: 'Create assignment',
                    onCancel: () => formSlot.replaceChildren(),
                    onSubmit: async (input) => {
                        const created = await labs.createAssignment(classId, input);
                        toast(`Created "${created.title}"`);
                        location.hash = `#/assignment/${created.id}`;
                    },
                    loadModel: (id) => session.rest.getModel(id).then((m) => m.model),
                }));
            } catch (e) {
                toast(errorText(e), 'error');
            }
        },
    }, 'New assignment') : null;

    // ---- the teacher's tools
    const act = async (work: () => Promise<unknown>, done?: string) => {
        try {
            await work();
            if (done) toast(done);
            rerender();
        } catch (e) {
            toast(errorText(e), 'error');
        }
    };
    const teacherTools = teacher ? h('div', { class: 'class-tools' },
        theClass.join_code ? h('div', { class: 'join-code-box' }, h('span', { class: 'muted' }, 'Join code '),
            h('code', { class: 'join-code', 'data-testid': 'join-code' }, theClass.join_code),
            h('button', {
                class: 'small', title: 'Copy the join code',
                onclick: () => void navigator.clipboard?.writeText(theClass.join_code!).then(() => toast('Join code copied'), () => undefined),
            }, 'Copy')) : null,
        h('button', {
            'data-testid': 'export-gradebook',
            onclick: async () => {
                try {
                    const csv = await labs.gradebookCsv(classId);
                    downloadText(`${theClass.name} gradebook.csv`, csv, 'text/csv');
                } catch (e) {
                    toast(errorText(e), 'error');
                }
            },
        }, 'Export gradebook'),
        h('button', {
            onclick: () => {
                const name = prompt('Class name', theClass.name);
                if (name && name !== theClass.name) void act(() => labs.updateClass(classId, { name }), 'Renamed');
            },
        }, 'Rename'),
        h('button', {
            'data-testid': 'archive-toggle',
            onclick: () => {
                const archive = !theClass.archived;
                if (archive && !confirm('Archive the class? It becomes read-only: no joins, edits, hand-ins or grades.')) return;
                void act(() => labs.updateClass(classId, { archived: archive }), archive ? 'Archived' : 'No longer archived');
            },
        }, theClass.archived ? 'Unarchive' : 'Archive')) : null;

    // ---- the gradebook (the teacher's), filled in when it comes
    const gradebookSlot = h('div', {}, h('p', { class: 'muted' }, 'Loading…'));
    if (teacher) {
        labs.gradebook(classId).then((book) => gradebookSlot.replaceChildren(gradebookTable(book)),
            (e) => gradebookSlot.replaceChildren(h('p', { class: 'form-error', role: 'alert' }, errorText(e))));
    }

    // ---- members
    const members = staff ? membersSection(session, theClass, teacher, rerender) : null;
    // ---- what the teacher shares live with the class
    const liveNow = liveNowSection(labs, classId);

    root.replaceChildren(h('main', { class: 'model-list-page lab-page', 'data-testid': 'class-page' },
        h('a', { href: '#/classes', class: 'back' }, '← Classes'),
        h('div', { class: 'lab-title' },
            h('h1', { 'data-testid': 'class-name' }, theClass.name),
            theClass.archived ? h('span', { class: 'badge', 'data-testid': 'archived' }, 'archived: read-only') : null,
            h('span', { class: 'muted' }, `teacher ${theClass.owner?.username ?? ''} · you: ${theClass.role ?? session.user?.role ?? ''}`)),
        teacherTools,
        liveNow.element,
        section('Assignments', 'assignments', newAssignment ? h('div', { class: 'toolbar' }, newAssignment) : null, formSlot, assignmentTable),
        teacher ? section('Gradebook', 'gradebook', gradebookSlot) : null,
        members));
    return liveNow;
}

function membersSection(session: Session, theClass: LabClass, teacher: boolean, rerender: () => void): HTMLElement {
    const labs = session.labs;
    const message = h('p', { class: 'form-error', role: 'alert' });
    const change = async (work: () => Promise<unknown>, done: string) => {
        message.textContent = '';
        try {
            await work();
            toast(done);
            rerender();
        } catch (e) {
            message.textContent = errorText(e);
        }
    };
    const memberList = [...(theClass.members ?? [])].sort((a, b) =>
        ROLES.indexOf(b.role) - ROLES.indexOf(a.role) || a.username.localeCompare(b.username));
    const row = (m: ClassMember) => {
        const self = m.id === session.user?.id;
        const editable = teacher && !self && !theClass.archived;
        const select = h('select', {
            'aria-label': `Role of ${m.username}`,
            onchange: () => void change(() => labs.setMember(theClass.id, m.id, select.value as ClassRole), `${m.username}: now ${select.value}`),
        }, ...ROLES.map((r) => h('option', { value: r, selected: r === m.role }, r)));
        const role = editable ? select : m.role;
        return h('tr', { 'data-username': m.username },
            h('td', {}, m.username, self ? h('span', { class: 'muted' }, ' (you)') : null),
            h('td', {}, role),
            h('td', {}, editable ? h('button', {
                class: 'danger small',
                onclick: () => {
                    if (confirm(`Remove ${m.username} from the class? They lose access at once.`)) {
                        void change(() => labs.removeMember(theClass.id, m.id), `Removed ${m.username}`);
                    }
                },
            }, 'Remove') : null));
    };
    const table = h('table', { class: 'model-table', 'data-testid': 'members-table' },
        h('thead', {}, h('tr', {}, h('th', {}, 'Member'), h('th', {}, 'Role'), h('th', {}, ''))),
        h('tbody', {}, ...memberList.map(row)));
    return section(`Members (${memberList.length})`, 'members', table, message,
        teacher && !theClass.archived ? importForm(session, theClass, rerender) : null);
}

/** User names in, accounts out: new ones with their generated password, shown this once. */
function importForm(session: Session, theClass: LabClass, rerender: () => void): HTMLElement {
    const text = h('textarea', { name: 'import-usernames', 'aria-label': 'User names to import', rows: 4, placeholder: 'one user name per line' });
    const message = h('p', { class: 'form-error', role: 'alert' });
    const result = h('div', { 'data-testid': 'import-result' });
    const button = h('button', { type: 'submit', class: 'primary' }, 'Import accounts');
    return h('form', {
        class: 'import-form', 'aria-label': 'Import accounts',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            message.textContent = '';
            const names = text.value.split(/\r?\n/).map((line) => line.split(',')[0].trim()).filter((n) => n !== '');
            if (names.length === 0) return;
            button.disabled = true;
            try {
                const accounts = await session.labs.importAccounts(theClass.id, names);
                text.value = '';
                const fresh = accounts.filter((a) => a.password);
                // the passwords are in this reply only: they stay on the page until the teacher leaves it
                const table = h('table', { class: 'model-table import-table' },
                    h('thead', {}, h('tr', {}, h('th', {}, 'User'), h('th', {}, 'Account'), h('th', {}, 'Password'))),
                    h('tbody', {}, ...accounts.map((a) => h('tr', { 'data-username': a.username },
                        h('td', {}, a.username),
                        h('td', { class: a.error ? 'form-error' : '' }, a.error ? `not created: ${a.error}` : a.created ? 'new' : 'existing'),
                        h('td', {}, a.password ? h('code', { class: 'password' }, a.password) : '—')))));
                result.replaceChildren(...[
                    fresh.length ? h('p', { class: 'notice' }, 'Give each new user their password now: it is not shown again.') : null,
                    table,
                    fresh.length ? h('button', {
                        type: 'button',
                        onclick: () => downloadText(`${theClass.name} accounts.csv`,
                            `username,password\n${fresh.map((a) => `${a.username},${a.password}`).join('\n')}\n`, 'text/csv'),
                    }, 'Download as CSV') : null,
                    h('button', { type: 'button', onclick: rerender }, 'Done')].filter((x) => x !== null));
            } catch (err) {
                message.textContent = errorText(err);
            } finally {
                button.disabled = false;
            }
        },
    }, h('h3', {}, 'Import accounts'),
    h('p', { class: 'muted' }, 'One user name per line (or a CSV whose first column is the user name). New accounts get a generated password; existing ones join as students.'),
    text, h('div', { class: 'toolbar' }, button), message, result);
}
