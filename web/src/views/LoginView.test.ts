// @vitest-environment jsdom
// The login page: a "Sign in with …" button per OpenID provider the server lists, each
// starting that provider's sign-in; a refused sign-in's reason above the form; the form alone
// when the server has no providers or cannot be asked.
import { describe, expect, it } from 'vitest';
import { renderLogin, signInFailureText } from './LoginView';
import type { Session } from '../app/Session';
import type { SignInProviders } from '../protocol/types';

const sessionListing = (methods: () => Promise<SignInProviders>) =>
    ({ rest: { signInProviders: methods } }) as unknown as Session;
const settle = () => new Promise((resolve) => setTimeout(resolve, 0));

describe('login page', () => {
    it('shows a button per provider that starts its sign-in, above the password form', async () => {
        document.body.replaceChildren();
        renderLogin(document.body, sessionListing(async () => ({
            providers: [{ name: 'university', display_name: 'University' }, { name: 'tu-graz', display_name: 'TU Graz' }],
            password_login: true,
        })), () => undefined);
        await settle();
        const buttons = [...document.querySelectorAll<HTMLAnchorElement>('a.sign-in-provider')];
        expect(buttons.map((b) => b.textContent)).toEqual(['Sign in with University', 'Sign in with TU Graz']);
        expect(buttons.map((b) => b.getAttribute('href'))).toEqual(
            ['/api/v1/auth/oidc/university/start', '/api/v1/auth/oidc/tu-graz/start']);
        expect(document.querySelector('input[name="username"]')).not.toBeNull();
    });

    it('without providers, or when they cannot be listed, is the form alone', async () => {
        const listings = [async () => ({ providers: [], password_login: true }), async () => { throw new Error('down'); }];
        for (const methods of listings) {
            document.body.replaceChildren();
            renderLogin(document.body, sessionListing(methods), () => undefined);
            await settle();
            expect(document.querySelectorAll('a.sign-in-provider')).toHaveLength(0);
            expect(document.querySelector('.sign-in-providers')?.textContent).toBe('');
            expect(document.querySelector('input[name="password"]')).not.toBeNull();
        }
    });

    it("says why a provider's sign-in came back refused", () => {
        document.body.replaceChildren();
        renderLogin(document.body, sessionListing(async () => ({ providers: [], password_login: true })), () => undefined,
            'no_account');
        expect(document.querySelector('[role="alert"]')?.textContent).toBe(signInFailureText('no_account'));
        expect(signInFailureText('no_account')).toContain('ask an administrator');
        expect(signInFailureText('sign_in_failed')).toContain('try again');
    });
});
