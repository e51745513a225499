// The account page: everyone changes their own password; an administrator also lists,
// creates and disables accounts and sets their roles, and finds the learning platforms' page.
import { h, errorText, toast } from '../ui/dom';
import type { Session } from '../app/Session';
import type { Account } from '../api/RestClient';
import type { User } from '../protocol/types';

const ROLES: User['role'][] = ['user', 'teacher', 'admin'];

function passwordForm(session: Session, onChanged: () => void): HTMLElement {
    const old = h('input', { type: 'password', name: 'old-password', autocomplete: 'current-password', required: true });
    const fresh = h('input', { type: 'password', name: 'new-password', autocomplete: 'new-password', required: true, minlength: 8 });
    const message = h('p', { class: 'form-error', role: 'alert' });
    return h('form', {
        class: 'account-form', 'aria-label': 'Change password',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            message.textContent = '';
            try {
                await session.rest.changePassword(old.value, fresh.value);
                // the server ends every session of the user, this one too
                toast('Password changed: log in with the new one.');
                onChanged();
            } catch (err) {
                message.textContent = errorText(err);
            }
        },
    }, h('h2', {}, 'Change your password'),
    h('label', {}, 'Current password', old), h('label', {}, 'New password', fresh),
    h('button', { type: 'submit', class: 'primary' }, 'Change password'), message);
}

function usersSection(session: Session): HTMLElement {
    const table = h('tbody');
    const message = h('p', { class: 'form-error', role: 'alert' });
    const refresh = async () => {
        try {
            const users = await session.rest.listUsers();
            table.replaceChildren(...users.sort((a, b) => a.username.localeCompare(b.username)).map(row));
        } catch (err) {
            message.textContent = errorText(err);
        }
    };
    const change = async (user: Account, patch: { role?: User['role']; disabled?: boolean }) => {
        message.textContent = '';
        try {
            await session.rest.updateUser(user.id, patch);
            toast(`${user.username}: ${patch.role ? `now ${patch.role}` : patch.disabled ? 'disabled' : 'enabled'}`);
        } catch (err) {
            message.textContent = `${user.username}: ${errorText(err)}`;
        }
        await refresh();
    };
    const row = (u: Account) => {
        const self = u.id === session.user?.id;
        const role = h('select', { 'aria-label': `Role of ${u.username}`, disabled: self, onchange: () => void change(u, { role: role.value as User['role'] }) },
            ...ROLES.map((r) => h('option', { value: r, selected: r === u.role }, r)));
        return h('tr', { 'data-username': u.username, class: u.disabled ? 'disabled-account' : '' },
            h('td', {}, u.username, self ? h('span', { class: 'muted' }, ' (you)') : null),
            h('td', {}, role),
            h('td', {}, u.disabled ? 'disabled' : 'active'),
            h('td', {}, self ? null : h('button', { class: u.disabled ? '' : 'danger', onclick: () => void change(u, { disabled: !u.disabled }) },
                u.disabled ? 'Enable' : 'Disable')));
    };
    const username = h('input', { name: 'new-username', required: true, 'aria-label': 'New user name' });
    const password = h('input', { name: 'new-user-password', type: 'password', autocomplete: 'new-password', required: true, 'aria-label': 'New user password' });
    const role = h('select', { name: 'new-user-role', 'aria-label': 'New user role' }, ...ROLES.map((r) => h('option', { value: r }, r)));
    const create = h('form', {
        class: 'toolbar', 'aria-label': 'Create user',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            message.textContent = '';
            try {
                const created = await session.rest.createUser(username.value.trim(), password.value, role.value as User['role']);
                toast(`Created ${created.username}`);
                username.value = '';
                password.value = '';
                await refresh();
            } catch (err) {
                message.textContent = errorText(err);
            }
        },
    }, username, password, role, h('button', { type: 'submit', class: 'primary' }, 'Create user'));
    void refresh();
    return h('section', { 'data-testid': 'accounts' }, h('h2', {}, 'Accounts'), create, message,
        h('table', { class: 'model-table' }, h('thead', {}, h('tr', {}, h('th', {}, 'User'), h('th', {}, 'Role'), h('th', {}, 'State'), h('th', {}, ''))), table));
}

export function renderAccounts(root: HTMLElement, session: Session, onLoggedOut: () => void): void {
    const admin = session.user?.role === 'admin';
    root.replaceChildren(h('main', { class: 'model-list-page accounts-page' },
        h('h1', {}, 'Account'),
        passwordForm(session, onLoggedOut),
        admin ? h('p', { class: 'admin-links' }, h('a', { href: '#/admin/lti', 'data-testid': 'admin-lti' }, 'Learning platforms (LTI)'),
            h('span', { class: 'muted' }, ': Moodle, Canvas and others that open tlmhub from their courses')) : null,
        admin ? usersSection(session) : null));
}
