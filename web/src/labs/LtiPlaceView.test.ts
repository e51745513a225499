// @vitest-environment jsdom
// Placing an assignment in a learning platform's course (#/lti-place/KEY): the class's
// assignments listed with the placement's platform and expiry, the placement posted for the
// assignment picked, and the signed answer handed to the platform as a form post of JWT; a key
// used or expired, a class without assignments, and other failures said in words.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { RestClient } from '../api/RestClient';
import { LabClient } from './LabClient';
import { EXPIRED_TEXT, renderLtiPlace } from './LtiPlaceView';
import type { Session } from '../app/Session';
import type { Assignment } from './types';

const settle = async () => { for (let i = 0; i < 4; ++i) await new Promise((resolve) => setTimeout(resolve, 0)); };

const assignment = (id: number, title: string): Assignment => ({
    id, class_id: 4, title, instructions: '', edit_mode: 'free', parameters: [], opens_at: 1765000000, due_at: 0,
    template_version: 1, has_solution: false, created_at: 1765000000, updated_at: 1765000000,
});
const LINK = { class_id: 4, platform: 'Moodle of the faculty', expires_at: 1765000600 };
const ANSWER = { return_url: 'https://moodle.uni.edu/mod/lti/contentitem_return.php?course=2', jwt: 'eyJ.eyJ.sig' };

interface Sent { method: string; url: string; body?: string }
type Reply = { status?: number; body?: unknown };

/** A session on a RestClient whose server answers from `routes` ("METHOD path" → reply). */
function fakeSession(routes: Record<string, Reply>) {
    const sent: Sent[] = [];
    const fetchFn = (async (url: string, init: RequestInit) => {
        sent.push({ method: init.method ?? 'GET', url, body: init.body as string | undefined });
        const reply = routes[`${init.method} ${url.replace('/api/v1', '')}`] ?? { status: 404, body: { error: { code: 'not_found', message: 'not found' } } };
        return new Response(JSON.stringify(reply.body ?? {}), { status: reply.status ?? 200 });
    }) as unknown as typeof fetch;
    const rest = new RestClient('tok', '/api/v1', fetchFn);
    const session = { user: { id: 2, username: 'tina', role: 'user' }, rest, labs: new LabClient(rest) } as unknown as Session;
    return { session, sent };
}

const SERVER: Record<string, Reply> = {
    'GET /lti/deep-links/DLKEY': { body: LINK },
    'GET /classes/4/assignments': { body: { assignments: [assignment(7, 'Spring and mass'), assignment(8, 'Damper')] } },
    'GET /classes/4': { body: { id: 4, name: 'Dynamics 1', owner: { id: 2, username: 'tina' }, archived: false, created_at: 1, role: 'teacher' } },
    'POST /lti/deep-links/DLKEY': { body: ANSWER },
};

async function open(routes: Record<string, Reply> = SERVER) {
    const fake = fakeSession(routes);
    const root = document.createElement('div');
    document.body.replaceChildren(root);
    await renderLtiPlace(root, fake.session, 'DLKEY');
    return { ...fake, root };
}

const placeButton = (title: string) => document.querySelector<HTMLButtonElement>(`button[aria-label="Place ${title} in the course"]`)!;

let submitted: HTMLFormElement[];
beforeEach(() => {
    submitted = [];
    vi.spyOn(HTMLFormElement.prototype, 'submit').mockImplementation(function (this: HTMLFormElement) { submitted.push(this); });
});
afterEach(() => vi.restoreAllMocks());

describe('placing an assignment in a course', () => {
    it('lists the class\'s assignments, each with a Place in course button, the platform and the expiry', async () => {
        const { sent } = await open();
        const rows = [...document.querySelectorAll('[data-testid="lti-place-table"] tbody tr')];
        expect(rows.map((r) => r.querySelector('a')!.textContent)).toEqual(['Spring and mass', 'Damper']);
        expect(rows.map((r) => r.querySelector('button')!.textContent)).toEqual(['Place in course', 'Place in course']);
        const page = document.querySelector('[data-testid="lti-place-page"]')!.textContent!;
        expect(page).toContain('Dynamics 1');
        expect(page).toContain('grade book of Moodle of the faculty');
        expect(document.querySelector('[data-testid="lti-place-expires"]')!.textContent).toMatch(/^This link expires at .+\.$/);
        expect(sent.map((s) => `${s.method} ${s.url}`)).toEqual(expect.arrayContaining(
            ['GET /api/v1/lti/deep-links/DLKEY', 'GET /api/v1/classes/4/assignments']));
    });

    it('posts the assignment picked and sends the signed answer to the platform as a form post of JWT', async () => {
        const { sent } = await open();
        placeButton('Damper').click();
        await settle();
        const post = sent.find((s) => s.method === 'POST')!;
        expect(post.url).toBe('/api/v1/lti/deep-links/DLKEY');
        expect(JSON.parse(post.body!)).toEqual({ assignment_id: 8 });
        expect(submitted).toHaveLength(1);
        const form = submitted[0];
        expect(form.method).toBe('post');
        expect(form.getAttribute('action')).toBe(ANSWER.return_url);
        expect(form.isConnected).toBe(true);
        const inputs = [...form.querySelectorAll('input')];
        expect(inputs.map((i) => [i.type, i.name, i.value])).toEqual([['hidden', 'JWT', ANSWER.jwt]]);
        // the key places once: no second placement from this page
        expect(placeButton('Spring and mass').disabled).toBe(true);
    });

    it('says the placement expired or was used when the key is not found', async () => {
        const { sent } = await open({ ...SERVER, 'GET /lti/deep-links/DLKEY': { status: 404, body: { error: { code: 'not_found', message: 'not found' } } } });
        expect(document.querySelector('[data-testid="lab-error"]')!.textContent).toBe(EXPIRED_TEXT);
        expect(EXPIRED_TEXT).toBe('This placement has expired or was used; add the activity again from the course.');
        expect(sent.some((s) => s.url.includes('/assignments'))).toBe(false);
    });

    it('says the placement expired when the platform\'s answer is refused with 404, and offers the buttons again on other failures', async () => {
        await open({ ...SERVER, 'POST /lti/deep-links/DLKEY': { status: 404, body: { error: { code: 'not_found', message: 'not found' } } } });
        placeButton('Damper').click();
        await settle();
        expect(document.querySelector('[data-testid="lti-place-error"]')!.textContent).toBe(EXPIRED_TEXT);
        expect(submitted).toHaveLength(0);

        await open({ ...SERVER, 'POST /lti/deep-links/DLKEY': { status: 500, body: { error: { code: 'internal', message: 'the key could not sign' } } } });
        placeButton('Damper').click();
        await settle();
        expect(document.querySelector('[data-testid="lti-place-error"]')!.textContent).toContain('the key could not sign');
        expect(placeButton('Damper').disabled).toBe(false);
        expect(placeButton('Damper').textContent).toBe('Place in course');
        expect(submitted).toHaveLength(0);
    });

    it('does not post to a return address that is not a web address', async () => {
        await open({ ...SERVER, 'POST /lti/deep-links/DLKEY': { body: { return_url: 'javascript:alert(1)', jwt: 'x' } } });
        placeButton('Damper').click();
        await settle();
        expect(submitted).toHaveLength(0);
        expect(document.querySelector('[data-testid="lti-place-error"]')!.textContent).toMatch(/no web address/);
    });

    it('says so when the class has no assignments, links to the class page and shows the expiry', async () => {
        await open({ ...SERVER, 'GET /classes/4/assignments': { body: { assignments: [] } } });
        const empty = document.querySelector('[data-testid="lti-place-empty"]')!;
        expect(empty.textContent).toContain('This class has no assignments yet.');
        expect(empty.querySelector<HTMLAnchorElement>('[data-testid="lti-place-class"]')!.getAttribute('href')).toBe('#/class/4');
        expect(empty.textContent).toMatch(/This link expires at /);
        expect(document.querySelector('[data-testid="lti-place-table"]')).toBeNull();
    });

    it('shows other failures in words', async () => {
        await open({ ...SERVER, 'GET /lti/deep-links/DLKEY': { status: 500, body: { error: { code: 'internal', message: 'the database is busy' } } } });
        expect(document.querySelector('[data-testid="lab-error"]')!.textContent).toContain('the database is busy');

        await open({ ...SERVER, 'GET /classes/4/assignments': { status: 403, body: { error: { code: 'forbidden', message: 'not a member of the class' } } } });
        expect(document.querySelector('[data-testid="lab-error"]')!.textContent).toContain('not a member of the class');
    });
});
