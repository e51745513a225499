// The classes page: the caller's classes with their role in each (searched by class or teacher,
// sorted by a column header), joining a class by its code and, for teachers (server role
// teacher or admin), creating one.
import { errorText, h } from '../ui/dom';
import { filterRows, sortableTable, type Column } from '../ui/sortableTable';
import { ApiError } from '../api/ApiError';
import type { Session } from '../app/Session';
import type { LabClass } from './types';
import { formatTime } from './format';

/** The server's refusal of a join code, in words. */
export function joinErrorText(e: unknown): string {
    if (e instanceof ApiError) {
        if (e.code === 'not_found') return 'No class has this code. Check the code your teacher gave you.';
        if (e.code === 'rate_limited') return `Too many wrong codes: wait a few minutes and try again. (${e.message})`;
        if (e.code === 'archived') return `This class is archived and takes no new members. (${e.message})`;
    }
    return errorText(e);
}

export async function renderClassList(root: HTMLElement, session: Session): Promise<void> {
    const labs = session.labs;
    const list = h('div', { 'data-testid': 'class-list' }, h('p', { class: 'muted' }, 'Loading…'));
    const roleOf = (c: LabClass) => c.role ?? (session.user?.role === 'admin' ? 'admin' : '');
    const columns: Column<LabClass>[] = [
        {
            key: 'name', label: 'Class', value: (c) => c.name,
            cell: (c) => h('span', {}, h('a', { href: `#/class/${c.id}`, class: 'class-link' }, c.name),
                c.archived ? h('span', { class: 'badge' }, 'archived') : null),
        },
        { key: 'teacher', label: 'Teacher', value: (c) => c.owner?.username ?? '' },
        { key: 'role', label: 'Your role', value: roleOf },
        { key: 'created', label: 'Created', value: (c) => c.created_at, largestFirst: true, cell: (c) => formatTime(c.created_at) },
    ];
    const refresh = async () => {
        try {
            const classes = await labs.listClasses();
            if (classes.length === 0) {
                list.replaceChildren(h('p', { class: 'muted' }, 'You are in no class yet. Join one with the code your teacher gave you.'));
                return;
            }
            const table = sortableTable({
                columns, rows: classes, order: { key: 'name', direction: 'ascending' }, empty: 'No class matches the search.',
                rowAttrs: (c) => ({ dataset: { classId: String(c.id) } }),
            });
            const search = h('input', {
                type: 'search', name: 'class-search', placeholder: 'Search classes by name or teacher', 'aria-label': 'Search classes',
                oninput: () => table.show(filterRows(classes, search.value, (c) => `${c.name} ${c.owner?.username ?? ''} ${roleOf(c)}`)),
            });
            list.replaceChildren(h('div', { class: 'list-search' }, search), table.element);
        } catch (e) {
            list.replaceChildren(h('p', { class: 'form-error', role: 'alert' }, errorText(e)));
        }
    };

    const code = h('input', { name: 'join-code', 'aria-label': 'Join code', placeholder: 'Code from your teacher', required: true, autocomplete: 'off', spellcheck: false });
    const joinError = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'join-error' });
    const joinButton = h('button', { type: 'submit', class: 'primary' }, 'Join');
    const join = h('form', {
        class: 'toolbar', 'aria-label': 'Join a class',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            joinError.textContent = '';
            joinButton.disabled = true;
            try {
                const joined = await labs.join(code.value.trim());
                location.hash = `#/class/${joined.id}`;
            } catch (err) {
                joinError.textContent = joinErrorText(err);
            } finally {
                joinButton.disabled = false;
            }
        },
    }, code, joinButton);

    const mayCreate = session.user?.role === 'teacher' || session.user?.role === 'admin';
    const name = h('input', { name: 'class-name', 'aria-label': 'Class name', placeholder: 'e.g. Fluid power 2026', required: true });
    const createError = h('p', { class: 'form-error', role: 'alert' });
    const create = h('form', {
        class: 'toolbar', 'aria-label': 'New class',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            createError.textContent = '';
            try {
                const created = await labs.createClass(name.value.trim());
                location.hash = `#/class/${created.id}`;
            } catch (err) {
                createError.textContent = errorText(err);
            }
        },
    }, name, h('button', { type: 'submit', class: 'primary' }, 'Create class'));

    root.replaceChildren(h('main', { class: 'model-list-page lab-page' },
        h('h1', {}, 'Classes'),
        list,
        h('section', { class: 'lab-section' }, h('h2', {}, 'Join a class'), join, joinError),
        mayCreate ? h('section', { class: 'lab-section' }, h('h2', {}, 'New class'), create, createError) : null));
    await refresh();
}
