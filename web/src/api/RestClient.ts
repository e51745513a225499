// REST client for /api/v1: bearer token, JSON in and out, errors as ApiError.
import { ApiError } from './ApiError';
import type {
    CatalogueEntry, FmuInterface, JobInfo, LtiDeepLink, LtiDeepLinkAnswer, LtiDeepLinkPlace, LtiPlatform, LtiPlatformList,
    LtiPlatformSettings, Model, ModelSummary, Preferences,
    ResultsJson, SignInProviders, User,
} from '../protocol/types';

export interface LoginResult { token: string; expires_at: number; user: User }

/** What an FMU export of a stored model offers beyond its interface components (docs/fmu.md). */
export interface FmuOptions { parameters: string[]; identifier?: string }

/** The user's settings kept on the server (GET/PUT /preferences): the display unit per quantity, e.g. { Pressure: 'bar' } (docs/units.md). */
export type { Preferences };

/** An account as the administrator sees it. */
export interface Account extends User { disabled: boolean }

/**
 * A GET the server answered 503 with Retry-After (it builds at most two of a user's large
 * replies at once, SECURITY.md) is sent again after the time it names, at most this often and
 * only when it names at most MAX_RETRY_AFTER_S seconds; other methods are never repeated.
 */
const BUSY_RETRIES = 3;
const MAX_RETRY_AFTER_S = 10;

export class RestClient {
    constructor(
        private token: string | null = null,
        private readonly base = '/api/v1',
        private readonly fetchFn: typeof fetch = (...args) => fetch(...args),
        private readonly wait: (ms: number) => Promise<void> = (ms) => new Promise((resolve) => setTimeout(resolve, ms)),
    ) {}

    /** Called when the server no longer accepts the token (expired, password changed, account disabled). */
    onUnauthorized: () => void = () => undefined;

    setToken(token: string | null): void { this.token = token; }
    getToken(): string | null { return this.token; }

    async call<T>(method: string, path: string, body?: unknown, contentType = 'application/json',
        accept = 'application/json'): Promise<T> {
        const headers: Record<string, string> = { Accept: accept };
        if (this.token) headers.Authorization = `Bearer ${this.token}`;
        let payload: string | undefined;
        if (body !== undefined) {
            headers['Content-Type'] = contentType;
            payload = typeof body === 'string' ? body : JSON.stringify(body);
        }
        const response = await this.fetchRetryingWhenBusy(path, { method, headers, body: payload });
        const text = await response.text();
        if (response.status === 401 && this.token && path !== '/auth/login') this.onUnauthorized();
        if (!response.ok) throw errorFromResponse(response.status, text);
        if (response.status === 204 || text === '') return undefined as T;
        if (accept === 'application/json') return JSON.parse(text) as T;
        return text as T;
    }

    /** A GET of binary content (a file to offer for download). */
    async blob(path: string, accept: string): Promise<Blob> {
        const headers: Record<string, string> = { Accept: accept };
        if (this.token) headers.Authorization = `Bearer ${this.token}`;
        const response = await this.fetchRetryingWhenBusy(path, { method: 'GET', headers });
        if (response.status === 401 && this.token) this.onUnauthorized();
        if (!response.ok) throw errorFromResponse(response.status, await response.text());
        return response.blob();
    }

    private async fetchRetryingWhenBusy(path: string, init: RequestInit): Promise<Response> {
        for (let attempt = 0; ; ++attempt) {
            const response = await this.fetchFn(this.base + path, init);
            const retryAfter = Number(response.headers.get('Retry-After'));
            if (init.method !== 'GET' || response.status !== 503 || attempt >= BUSY_RETRIES ||
                !response.headers.has('Retry-After') || !(retryAfter >= 0 && retryAfter <= MAX_RETRY_AFTER_S)) {
                return response;
            }
            await response.text();   // the refusal's body, not needed
            await this.wait(retryAfter * 1000);
        }
    }

    login(username: string, password: string): Promise<LoginResult> {
        return this.call('POST', '/auth/login', { username, password });
    }
    /** How to sign in: the OpenID providers' buttons, and whether passwords log in everyone. */
    signInProviders(): Promise<SignInProviders> { return this.call('GET', '/auth/providers'); }
    /** The login of a provider sign-in, by the one-time key its end handed to the app. */
    collectSignIn(key: string): Promise<LoginResult> { return this.call('POST', '/auth/oidc/collect', { key }); }
    logout(): Promise<void> { return this.call('POST', '/auth/logout'); }
    me(): Promise<User> { return this.call('GET', '/auth/me'); }
    changePassword(oldPassword: string, newPassword: string): Promise<void> {
        return this.call('POST', '/auth/password', { old_password: oldPassword, new_password: newPassword });
    }

    preferences(): Promise<Preferences> { return this.call('GET', '/preferences'); }
    /** Replaces the stored preferences; answers them as stored. */
    setPreferences(preferences: Preferences): Promise<Preferences> { return this.call('PUT', '/preferences', preferences); }

    listUsers(): Promise<Account[]> { return this.call('GET', '/users'); }
    createUser(username: string, password: string, role: User['role']): Promise<Account> {
        return this.call('POST', '/users', { username, password, role });
    }
    updateUser(id: number, change: { role?: User['role']; disabled?: boolean }): Promise<Account> {
        return this.call('PATCH', `/users/${id}`, change);
    }

    /** The registered LTI platforms and this tool's own addresses (administrators). */
    ltiPlatforms(): Promise<LtiPlatformList> { return this.call('GET', '/admin/lti/platforms'); }
    createLtiPlatform(settings: LtiPlatformSettings): Promise<LtiPlatform> {
        return this.call('POST', '/admin/lti/platforms', settings);
    }
    updateLtiPlatform(id: number, settings: LtiPlatformSettings): Promise<LtiPlatform> {
        return this.call('PUT', `/admin/lti/platforms/${id}`, settings);
    }
    /** Removes the platform with its course links, line items and pending scores (the classes stay). */
    deleteLtiPlatform(id: number): Promise<void> { return this.call('DELETE', `/admin/lti/platforms/${id}`); }
    /** A deep-linking launch's placement (its teacher only): the class whose assignments may be placed. */
    ltiDeepLink(key: string): Promise<LtiDeepLink> {
        return this.call('GET', `/lti/deep-links/${encodeURIComponent(key)}`);
    }
    /** Places an assignment (once per key): the signed answer the browser posts to the platform. */
    placeLtiDeepLink(key: string, assignmentId: number): Promise<LtiDeepLinkAnswer> {
        const place: LtiDeepLinkPlace = { assignment_id: assignmentId };
        return this.call('POST', `/lti/deep-links/${encodeURIComponent(key)}`, place);
    }

    listModels(): Promise<ModelSummary[]> { return this.call('GET', '/models'); }
    getModel(id: number): Promise<ModelSummary & { model: Model; writable?: boolean }> { return this.call('GET', `/models/${id}`); }
    createModel(name: string): Promise<ModelSummary> { return this.call('POST', '/models', { name }); }
    duplicateModel(id: number, name: string): Promise<ModelSummary> {
        return this.call('POST', '/models', { name, copy_of: id });
    }
    uploadHmf(hmf: string, name?: string): Promise<ModelSummary> {
        const query = name ? `?name=${encodeURIComponent(name)}` : '';
        return this.call('POST', `/models${query}`, hmf, 'application/xml');
    }
    downloadHmf(id: number): Promise<string> {
        return this.call('GET', `/models/${id}?format=hmf`, undefined, undefined, 'application/xml');
    }
    renameModel(id: number, name: string): Promise<ModelSummary> {
        return this.call('PUT', `/models/${id}`, { name });
    }
    deleteModel(id: number): Promise<void> { return this.call('DELETE', `/models/${id}`); }
    fmuInterface(id: number, options: FmuOptions): Promise<FmuInterface> {
        return this.call('GET', `/models/${id}/fmu/interface${fmuQuery(options)}`);
    }
    downloadFmu(id: number, options: FmuOptions): Promise<Blob> {
        return this.blob(`/models/${id}/fmu${fmuQuery(options)}`, 'application/zip');
    }

    components(): Promise<CatalogueEntry[]> { return this.call('GET', '/components'); }

    job(id: number): Promise<JobInfo> { return this.call('GET', `/jobs/${id}`); }
    /** A model's runs, newest first, at most `limit`; `before` (a job id) asks for the runs older than it. */
    runHistory(modelId: number, limit?: number, before?: number): Promise<JobInfo[]> {
        const query = [`model_id=${modelId}`];
        if (limit !== undefined) query.push(`limit=${limit}`);
        if (before !== undefined) query.push(`before=${before}`);
        return this.call('GET', `/jobs?${query.join('&')}`);
    }
    /** Names or pins a run (its owner only); answers the updated run. */
    labelJob(id: number, change: { name?: string; pinned?: boolean }): Promise<JobInfo> {
        return this.call('PATCH', `/jobs/${id}`, change);
    }
    resultsJson(id: number, variables: string[]): Promise<ResultsJson> {
        const list = variables.map(encodeURIComponent).join(',');
        return this.call('GET', `/jobs/${id}/results?format=json&variables=${list}`);
    }
    /** The names of a run's logged variables (a recorded live session logs only what it recorded). */
    async loggedVariables(id: number): Promise<string[]> {
        const reply: { variables: { name: string }[] } = await this.call('GET', `/jobs/${id}/variables`);
        return reply.variables.map((v) => v.name);
    }
    resultsCsv(id: number, variables: string[]): Promise<string> {
        const list = variables.map(encodeURIComponent).join(',');
        return this.call('GET', `/jobs/${id}/results?format=csv&variables=${list}`, undefined, undefined, 'text/csv');
    }
}

/** ?parameters=A.x,B.y&identifier=Name, leaving out what is not set. */
export function fmuQuery(options: FmuOptions): string {
    const query: string[] = [];
    if (options.parameters.length > 0) query.push(`parameters=${options.parameters.map(encodeURIComponent).join(',')}`);
    if (options.identifier) query.push(`identifier=${encodeURIComponent(options.identifier)}`);
    return query.length > 0 ? `?${query.join('&')}` : '';
}

function errorFromResponse(status: number, text: string): ApiError {
    try {
        const body = JSON.parse(text) as { error?: { code?: string; message?: string } };
        if (body.error?.code) return new ApiError(body.error.code, body.error.message ?? body.error.code, status);
    } catch {
        // not JSON: fall through to a generic error
    }
    return new ApiError(status === 404 ? 'not_found' : 'http_error', text || `HTTP ${status}`, status);
}
