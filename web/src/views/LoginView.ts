// Login page: a button per OpenID provider the server has (GET /auth/providers), and the
// form for this server's own and a directory's passwords.
import { h, errorText } from '../ui/dom';
import type { Session } from '../app/Session';

/** What the login page says when a sign-in through a provider came back refused (#/sign-in-failed/CODE). */
export function signInFailureText(code: string): string {
    switch (code) {
    case 'no_account': return 'Your organisation knows you, but this server makes no accounts on first sign-in: ask an administrator.';
    case 'account_disabled': return 'This account is disabled; ask an administrator.';
    case 'expired': return 'That sign-in has expired or was used already; sign in again.';
    case 'provider_unavailable': return 'Your organisation\'s sign-in cannot be reached now; try again later.';
    case 'busy': return 'Too many sign-ins are under way; try again in a minute.';
    default: return 'The sign-in did not succeed; try again. (The server\'s log says why.)';
    }
}

export function renderLogin(root: HTMLElement, session: Session, onLoggedIn: () => void, failure?: string): void {
    const username = h('input', { name: 'username', autocomplete: 'username', required: true, autofocus: true });
    const password = h('input', { name: 'password', type: 'password', autocomplete: 'current-password', required: true });
    const message = h('p', { class: 'form-error', role: 'alert' }, failure ? signInFailureText(failure) : '');
    const providers = h('div', { class: 'sign-in-providers' });
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
    providers,
    h('label', {}, 'User name', username),
    h('label', {}, 'Password', password),
    button,
    message);
    root.replaceChildren(h('main', { class: 'login-page' }, form));
    void session.rest.signInProviders().then((methods) => {
        providers.replaceChildren(...methods.providers.map((p) => h('a', {
            class: 'button sign-in-provider', href: `/api/v1/auth/oidc/${encodeURIComponent(p.name)}/start`,
        }, `Sign in with ${p.display_name}`)));
        if (methods.providers.length > 0) providers.append(h('p', { class: 'muted' }, 'or with a user name and password'));
    }).catch(() => undefined);   // the form still works
}
