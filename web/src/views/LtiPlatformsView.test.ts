// @vitest-environment jsdom
// The administrator's page of learning platforms (#/admin/lti): the tool's addresses to copy
// into the platform, the registered platforms, the form's checks (the server's, in the
// browser), a refused save with the server's message, and removing with a confirmation.
import { afterEach, describe, expect, it, vi } from 'vitest';
import { checkPlatform, deploymentIds, MAX_DEPLOYMENTS, renderLtiPlatforms, toolAddresses, type PlatformInput } from './LtiPlatformsView';
import { ApiError } from '../api/ApiError';
import type { Session } from '../app/Session';
import type { LtiPlatform, LtiPlatformList, LtiPlatformSettings, LtiToolSettings } from '../protocol/types';

const settle = () => new Promise((resolve) => setTimeout(resolve, 0));

const TOOL: LtiToolSettings = {
    enabled: true,
    login_url: 'https://tlmhub.uni.edu/api/v1/lti/login',
    launch_url: 'https://tlmhub.uni.edu/api/v1/lti/launch',
    deep_link_url: 'https://tlmhub.uni.edu/api/v1/lti/launch',
    jwks_url: 'https://tlmhub.uni.edu/api/v1/lti/jwks',
};
const MOODLE: LtiPlatform = {
    id: 1, name: 'Moodle of the faculty', issuer: 'https://moodle.uni.edu', client_id: 'f1x4Q2',
    auth_url: 'https://moodle.uni.edu/mod/lti/auth.php', token_url: 'https://moodle.uni.edu/mod/lti/token.php',
    jwks_url: 'https://moodle.uni.edu/mod/lti/certs.php', deployment_ids: ['1'], created_at: 1765000000,
};
const GOOD: PlatformInput = {
    name: 'Canvas', issuer: 'https://canvas.instructure.com', client_id: '10000000000001',
    auth_url: 'https://sso.canvaslms.com/api/lti/authorize_redirect', token_url: 'https://sso.canvaslms.com/login/oauth2/token',
    jwks_url: 'https://sso.canvaslms.com/api/lti/security/jwks', deployment_ids: '7:abc, 8:def\n9:ghi\n',
};

/** A server of platforms in memory, behind the RestClient's methods the page calls. */
function fakeSession(initial: LtiPlatform[] = [MOODLE], tool: LtiToolSettings = TOOL, role = 'admin') {
    let platforms = structuredClone(initial);
    let nextId = 10;
    const rest = {
        ltiPlatforms: vi.fn(async (): Promise<LtiPlatformList> => ({ platforms: structuredClone(platforms), tool })),
        createLtiPlatform: vi.fn(async (s: LtiPlatformSettings): Promise<LtiPlatform> => {
            if (platforms.some((p) => p.issuer === s.issuer && p.client_id === s.client_id)) {
                throw new ApiError('conflict', 'a platform with this issuer and client id is already registered', 409);
            }
            const created = { ...s, id: nextId++, created_at: 1765000100 };
            platforms.push(created);
            return created;
        }),
        updateLtiPlatform: vi.fn(async (id: number, s: LtiPlatformSettings): Promise<LtiPlatform> => {
            const i = platforms.findIndex((p) => p.id === id);
            platforms[i] = { ...platforms[i], ...s };
            return platforms[i];
        }),
        deleteLtiPlatform: vi.fn(async (id: number) => { platforms = platforms.filter((p) => p.id !== id); }),
    };
    return { session: { user: { id: 1, username: 'admin', role }, rest } as unknown as Session, rest };
}

async function openPage(...args: Parameters<typeof fakeSession>) {
    document.body.replaceChildren();
    const fake = fakeSession(...args);
    renderLtiPlatforms(document.body, fake.session);
    await settle();
    return fake;
}

const field = (label: string) => {
    const labelEl = [...document.querySelectorAll('label')].find((l) => l.textContent === label)!;
    return document.getElementById(labelEl.htmlFor) as HTMLInputElement | HTMLTextAreaElement;
};
const fill = (input: PlatformInput) => {
    const labels: Record<keyof PlatformInput, string> = {
        name: 'Name', issuer: 'Issuer', client_id: 'Client id', auth_url: 'Authentication URL', token_url: 'Token URL',
        jwks_url: 'Keyset URL', deployment_ids: 'Deployment ids',
    };
    for (const [key, label] of Object.entries(labels)) field(label).value = input[key as keyof PlatformInput];
};
const submit = async () => {
    document.querySelector<HTMLFormElement>('form.lti-form')!.requestSubmit();
    await settle();
    await settle();
};
const rows = () => [...document.querySelectorAll<HTMLTableRowElement>('[data-testid="lti-platforms"] tbody tr')];
const errorOf = (label: string) => document.getElementById(`${field(label).id}-error`)!;

afterEach(() => {
    vi.unstubAllGlobals();
});

describe('learning platforms page', () => {
    it("shows the tool's addresses by Moodle's names, each with a Copy button, and the registered platforms", async () => {
        const writeText = vi.fn(async () => undefined);
        vi.stubGlobal('navigator', { clipboard: { writeText } });
        await openPage();
        const tool = document.querySelector('[data-testid="lti-tool"]')!;
        const shown = [...tool.querySelectorAll('tbody tr')].map((r) => [r.querySelector('th')!.firstChild!.textContent, r.querySelector('code')?.textContent]);
        expect(shown).toEqual([
            ['Tool URL', TOOL.launch_url],
            ['Initiate login URL', TOOL.login_url],
            ['Redirection URI(s)', TOOL.launch_url],   // launch and deep linking share the address: once
            ['Public keyset URL', TOOL.jwks_url],
            ['Content Selection URL', TOOL.deep_link_url],
        ]);
        expect(document.querySelector('[data-testid="lti-off"]')).toBeNull();
        tool.querySelector<HTMLButtonElement>('button[aria-label="Copy Initiate login URL"]')!.click();
        expect(writeText).toHaveBeenCalledWith(TOOL.login_url);

        expect(rows()).toHaveLength(1);
        const cells = [...rows()[0].cells].map((c) => c.textContent);
        expect(cells.slice(0, 4)).toEqual(['Moodle of the faculty', 'https://moodle.uni.edu', 'f1x4Q2', '1']);
        expect(cells[4]).toMatch(/2025/);
        expect(rows()[0].querySelector('button[aria-label="Edit Moodle of the faculty"]')).not.toBeNull();
        expect(rows()[0].querySelector('button[aria-label="Remove Moodle of the faculty"]')).not.toBeNull();
    });

    it('lists both redirection addresses when deep linking has its own', () => {
        const redirects = toolAddresses({ ...TOOL, deep_link_url: 'https://tlmhub.uni.edu/api/v1/lti/deep-link' })
            .find((a) => a.label === 'Redirection URI(s)')!;
        expect(redirects.value).toBe('https://tlmhub.uni.edu/api/v1/lti/launch\nhttps://tlmhub.uni.edu/api/v1/lti/deep-link');
    });

    it('says launches are off until the server has its key file and public address', async () => {
        await openPage([], { enabled: false, login_url: '', launch_url: '', deep_link_url: '', jwks_url: '' });
        const notice = document.querySelector('[data-testid="lti-off"]')!;
        expect(notice.textContent).toContain('--lti-key-file');
        expect(notice.textContent).toContain('--public-url');
        expect(document.querySelector<HTMLButtonElement>('button[aria-label="Copy Tool URL"]')!.disabled).toBe(true);
        expect(rows()).toHaveLength(0);
        expect(document.body.textContent).toContain('No platform is registered yet.');
    });

    it('is for administrators only', async () => {
        const { rest } = await openPage([MOODLE], TOOL, 'teacher');
        expect(document.body.textContent).toContain('Only administrators');
        expect(rest.ltiPlatforms).not.toHaveBeenCalled();
    });

    it('labels every field of the form for keyboards and screen readers', async () => {
        await openPage();
        for (const label of ['Name', 'Issuer', 'Client id', 'Authentication URL', 'Token URL', 'Keyset URL', 'Deployment ids']) {
            const input = field(label);
            expect(input, label).not.toBeNull();
            const described = input.getAttribute('aria-describedby')!.split(' ').map((id) => document.getElementById(id));
            expect(described.every((el) => el !== null), label).toBe(true);
        }
        expect(document.querySelector('form.lti-form')!.getAttribute('aria-labelledby')).toBeTruthy();
    });

    it('registers a platform, its deployment ids separated by commas or lines', async () => {
        const { rest } = await openPage();
        fill(GOOD);
        await submit();
        expect(rest.createLtiPlatform).toHaveBeenCalledWith({
            name: 'Canvas', issuer: 'https://canvas.instructure.com', client_id: '10000000000001',
            auth_url: GOOD.auth_url, token_url: GOOD.token_url, jwks_url: GOOD.jwks_url, deployment_ids: ['7:abc', '8:def', '9:ghi'],
        });
        expect(rows().map((r) => r.cells[0].textContent)).toEqual(['Canvas', 'Moodle of the faculty']);
        expect(rows()[0].cells[3].textContent).toBe('7:abc, 8:def, 9:ghi');
        expect(field('Name').value).toBe('');   // ready for the next
    });

    it('checks the form as the server does before sending it', async () => {
        const { rest } = await openPage();
        await submit();
        expect(errorOf('Name').textContent).toBe('Give the platform a name.');
        expect(errorOf('Issuer').textContent).toBe('The issuer is missing.');
        expect(errorOf('Deployment ids').textContent).toBe('List at least one deployment id.');
        expect(field('Issuer').getAttribute('aria-invalid')).toBe('true');
        expect(document.activeElement).toBe(field('Name'));

        fill({ ...GOOD, issuer: 'http://canvas.instructure.com', token_url: 'https://sso.canvaslms.com/login/oauth 2/token',
            deployment_ids: Array.from({ length: MAX_DEPLOYMENTS + 1 }, (_, i) => String(i)).join(',') });
        await submit();
        expect(errorOf('Name').hidden).toBe(true);
        expect(field('Name').getAttribute('aria-invalid')).toBe('false');
        expect(errorOf('Issuer').textContent).toBe('The issuer must be an https:// address.');
        expect(errorOf('Token URL').textContent).toBe('The token URL must be an https:// address without spaces.');
        expect(errorOf('Deployment ids').textContent).toBe('At most 100 deployment ids (not 101).');
        expect(document.querySelector('[data-testid="lti-form-error"]')!.textContent).toContain('need a change');
        expect(rest.createLtiPlatform).not.toHaveBeenCalled();
    });

    it('reads deployment ids and refuses the same one twice or overlong names', () => {
        expect(deploymentIds(' 1, 2\r\n3,,\n\n 4 ')).toEqual(['1', '2', '3', '4']);
        expect(checkPlatform({ ...GOOD, deployment_ids: '1, 2, 1' }).errors.deployment_ids).toBe('The deployment id "1" is listed twice.');
        expect(checkPlatform({ ...GOOD, deployment_ids: 'x'.repeat(256) }).errors.deployment_ids).toContain('at most 255 characters');
        expect(checkPlatform({ ...GOOD, name: 'n'.repeat(101) }).errors.name).toBe('The name must be at most 100 characters long.');
        expect(checkPlatform({ ...GOOD, client_id: '   ' }).errors.client_id).toBe('The client id is missing.');
        expect(checkPlatform({ ...GOOD, name: 'Moodle\u202e' }).errors.name).toBe('The name must not contain control characters.');
        expect(checkPlatform({ ...GOOD, client_id: 'a\tb' }).errors.client_id).toBe('The client id must not contain control characters.');
        expect(checkPlatform(GOOD).settings?.deployment_ids).toEqual(['7:abc', '8:def', '9:ghi']);
    });

    it("shows the server's message when it refuses a save (a platform registered already)", async () => {
        const { rest } = await openPage();
        fill({ ...GOOD, issuer: MOODLE.issuer, client_id: MOODLE.client_id });
        await submit();
        expect(rest.createLtiPlatform).toHaveBeenCalledTimes(1);
        const message = document.querySelector('[data-testid="lti-form-error"]')!;
        expect(message.getAttribute('role')).toBe('alert');
        expect(message.textContent).toBe('a platform with this issuer and client id is already registered');
        expect(field('Issuer').getAttribute('aria-invalid')).toBe('true');
        expect(field('Client id').getAttribute('aria-invalid')).toBe('true');
        expect(field('Name').value).toBe('Canvas');   // kept, to correct
        expect(rows()).toHaveLength(1);
    });

    it("shows a validation refusal in words, marking the field it names", async () => {
        const { rest } = await openPage();
        rest.createLtiPlatform.mockRejectedValueOnce(new ApiError('bad_request', 'body.jwks_url: does not match the pattern "^https://[^\\s]+$"', 400));
        fill(GOOD);
        await submit();
        expect(document.querySelector('[data-testid="lti-form-error"]')!.textContent).toBe('The keyset URL is not in the expected form.');
        expect(field('Keyset URL').getAttribute('aria-invalid')).toBe('true');
    });

    it('edits a platform in the same form', async () => {
        const { rest } = await openPage();
        rows()[0].querySelector<HTMLButtonElement>('button[aria-label^="Edit"]')!.click();
        expect(document.querySelector('form.lti-form h2')!.textContent).toBe('Edit "Moodle of the faculty"');
        expect(field('Issuer').value).toBe(MOODLE.issuer);
        expect(document.activeElement).toBe(field('Name'));
        field('Deployment ids').value = '1\n2';
        field('Name').value = 'Moodle';
        await submit();
        expect(rest.updateLtiPlatform).toHaveBeenCalledWith(1, expect.objectContaining({ name: 'Moodle', deployment_ids: ['1', '2'] }));
        expect(rows()[0].cells[0].textContent).toBe('Moodle');
        expect(document.querySelector('form.lti-form h2')!.textContent).toBe('Register a platform');
    });

    it('removes a platform only when the administrator confirms', async () => {
        const { rest } = await openPage();
        const confirm = vi.fn((_message: string) => false);
        vi.stubGlobal('confirm', confirm);
        const remove = () => rows()[0].querySelector<HTMLButtonElement>('button[aria-label^="Remove"]')!.click();
        remove();
        await settle();
        expect(confirm.mock.calls[0][0]).toMatch(/^Remove "Moodle of the faculty"\? its course links, line items and pending scores go with it; the classes stay/i);
        expect(rest.deleteLtiPlatform).not.toHaveBeenCalled();
        expect(rows()).toHaveLength(1);

        confirm.mockReturnValue(true);
        remove();
        await settle();
        await settle();
        expect(rest.deleteLtiPlatform).toHaveBeenCalledWith(1);
        expect(rows()).toHaveLength(0);
    });
});
