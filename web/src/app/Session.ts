// The logged-in user: token kept in sessionStorage (per tab) so a reload stays logged in.
import { RestClient, type LoginResult } from '../api/RestClient';
import { LabClient } from '../labs/LabClient';
import type { User } from '../protocol/types';
import { UnitPreferences } from '../run/unitPreferences';
import { errorText, toast } from '../ui/dom';

const TOKEN_KEY = 'tlmhub.token';

export class Session {
    readonly rest = new RestClient(sessionStorage.getItem(TOKEN_KEY));
    readonly labs = new LabClient(this.rest);
    /** The user's display units, loaded when plots first open. */
    readonly units = new UnitPreferences(this.rest, (e) => toast(`The unit was not saved: ${errorText(e)}`, 'error'));
    user: User | null = null;

    constructor() {
        // a session the server ended leads back to the login page
        this.rest.onUnauthorized = () => {
            this.forget();
            location.hash = '#/login';
        };
    }

    get token(): string | null { return this.rest.getToken(); }

    async login(username: string, password: string): Promise<User> {
        return this.adopt(await this.rest.login(username, password));
    }

    /** Finishes a sign-in through a provider: the key of #/signed-in/KEY, traded once. */
    async collectSignIn(key: string): Promise<User> {
        return this.adopt(await this.rest.collectSignIn(key));
    }

    private adopt(result: LoginResult): User {
        // another user may have been logged in in this tab
        this.units.forget();
        this.rest.setToken(result.token);
        sessionStorage.setItem(TOKEN_KEY, result.token);
        this.user = result.user;
        return result.user;
    }

    /** Checks a stored token; false when there is none or it expired. */
    async restore(): Promise<boolean> {
        if (!this.token) return false;
        try {
            this.user = await this.rest.me();
            return true;
        } catch {
            this.forget();
            return false;
        }
    }

    async logout(): Promise<void> {
        try {
            await this.rest.logout();
        } finally {
            this.forget();
        }
    }

    private forget(): void {
        this.rest.setToken(null);
        sessionStorage.removeItem(TOKEN_KEY);
        this.user = null;
        this.units.forget();
    }
}
