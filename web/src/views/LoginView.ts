// Login form.
import { h, errorText } from '../ui/dom';
import type { Session } from '../app/Session';

export function renderLogin(root: HTMLElement, session: Session, onLoggedIn: () => void): void {
    const username = h('input', { name: 'username', autocomplete: 'username', required: true, autofocus: true });
    const password = h('input', { name: 'password', type: 'password', autocomplete: 'current-password', required: true });
    const message = h('p', { class: 'form-error', role: 'alert' });
    const button = h('button', { type: 'submit', class: 'primary' }, 'Log in');
    const form = h('form', {
        class: 'login-form',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            button.disabled = true;
            message.textContent = '';
            try {
                await session.login(username.value.trim(), password.value);
                onLoggedIn();
            } catch (err) {
                message.textContent = errorText(err);
            } finally {
                button.disabled = false;
            }
        },
    },
    h('h1', {}, 'tlmhub'),
    h('p', { class: 'muted' }, 'Hydraulic, mechanic, electric and control system simulation'),
    h('label', {}, 'User name', username),
    h('label', {}, 'Password', password),
    button,
    message);
    root.replaceChildren(h('main', { class: 'login-page' }, form));
}
