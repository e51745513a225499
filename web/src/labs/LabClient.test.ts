// The lab calls go to the paths, with the methods and bodies of docs/labs.md, and unwrap the
// server's reply objects; errors carry the server's code (e.g. rate_limited).
import { describe, expect, it } from 'vitest';
import { RestClient } from '../api/RestClient';
import { ApiError } from '../api/ApiError';
import { LabClient } from './LabClient';

interface Sent { method: string; url: string; body?: string; headers: Record<string, string> }

function fake(reply: (sent: Sent) => { status?: number; body?: unknown }) {
    const sent: Sent[] = [];
    const fetchFn = (async (url: string, init: RequestInit) => {
        const s: Sent = { method: init.method ?? 'GET', url, body: init.body as string | undefined, headers: init.headers as Record<string, string> };
        sent.push(s);
        const r = reply(s);
        const text = r.body === undefined ? '' : typeof r.body === 'string' ? r.body : JSON.stringify(r.body);
        return new Response(r.status === 204 ? null : text, { status: r.status ?? 200 });
    }) as unknown as typeof fetch;
    const labs = new LabClient(new RestClient('tok', '/api/v1', fetchFn));
    return { labs, sent };
}

describe('LabClient', () => {
    it('sends each call to its path with its method and body', async () => {
        const { labs, sent } = fake((s) => {
            if (s.url.endsWith('/classes') && s.method === 'GET') return { body: { classes: [{ id: 1, name: 'C', role: 'teacher' }] } };
            if (s.url.endsWith('/assignments') && s.method === 'GET') return { body: { assignments: [{ id: 4 }] } };
            if (s.url.endsWith('/open') || s.url.endsWith('/reset')) return { body: { copy: { model_id: 9, template_version: 1, outdated: false } } };
            if (s.url.endsWith('/handins')) return { body: { handins: [{ id: 7 }] } };
            if (s.url.endsWith('/dashboard')) return { body: { students: [{ student: { id: 2, username: 's' } }] } };
            if (s.url.endsWith('/checks') && s.method === 'GET') return { body: { checks: [{ name: 'c', points: 1, pretest: true }] } };
            if (s.url.endsWith('/comments') && s.method === 'GET') return { body: { comments: [{ id: 1, text: 'hi' }] } };
            if (s.url.includes('/import')) return { body: { accounts: [{ username: 'x', password: 'p', created: true }] } };
            if (s.url.includes('gradebook?format=csv')) return { body: 'student,total\r\nx,1\r\n' };
            if (s.method === 'DELETE') return { status: 204 };
            return { body: { id: 1 } };
        });
        expect(await labs.listClasses()).toEqual([{ id: 1, name: 'C', role: 'teacher' }]);
        await labs.createClass('Lab 1');
        await labs.getClass(3);
        await labs.updateClass(3, { archived: true });
        await labs.join('ABCDEFGHJKLM');
        expect(await labs.importAccounts(3, ['  username', 'x', '', 'y '])).toEqual([{ username: 'x', password: 'p', created: true }]);
        await labs.setMember(3, 8, 'assistant');
        await labs.removeMember(3, 8);
        expect(await labs.gradebookCsv(3)).toBe('student,total\r\nx,1\r\n');
        expect(await labs.listAssignments(3)).toEqual([{ id: 4 }]);
        await labs.createAssignment(3, { title: 'T', template_model_id: 12, edit_mode: 'parameters', parameters: [{ name: 'P.k', min: 0, max: 100 }] });
        await labs.getAssignment(4);
        await labs.updateAssignment(4, { due_at: 0 });
        await labs.putChecks(4, [{ name: 'c', points: 2, pretest: true, definition: { kind: 'curve', variable: 'Mass#P1#x', tolerance: 0.05 } }]);
        expect(await labs.getChecks(4)).toEqual([{ name: 'c', points: 1, pretest: true }]);
        expect(await labs.open(4)).toEqual({ model_id: 9, template_version: 1, outdated: false });
        await labs.reset(4);
        await labs.pretest(4);
        await labs.handIn(4);
        expect(await labs.handIns(4)).toEqual([{ id: 7 }]);
        await labs.handIns(4, 2);
        expect(await labs.dashboard(4)).toEqual([{ student: { id: 2, username: 's' } }]);
        await labs.overlay(4, 'Mass#P1#x', 200);
        await labs.getHandIn(7);
        expect(await labs.comments(7)).toEqual([{ id: 1, text: 'hi' }]);
        await labs.addComment(7, 'Well done');
        await labs.setGrade(7, null);
        await labs.deleteAssignment(4);
        await labs.deleteClass(3);

        expect(sent.map((s) => `${s.method} ${s.url}`)).toEqual([
            'GET /api/v1/classes',
            'POST /api/v1/classes',
            'GET /api/v1/classes/3',
            'PATCH /api/v1/classes/3',
            'POST /api/v1/classes/join',
            'POST /api/v1/classes/3/import',
            'PUT /api/v1/classes/3/members/8',
            'DELETE /api/v1/classes/3/members/8',
            'GET /api/v1/classes/3/gradebook?format=csv',
            'GET /api/v1/classes/3/assignments',
            'POST /api/v1/classes/3/assignments',
            'GET /api/v1/assignments/4',
            'PATCH /api/v1/assignments/4',
            'PUT /api/v1/assignments/4/checks',
            'GET /api/v1/assignments/4/checks',
            'POST /api/v1/assignments/4/open',
            'POST /api/v1/assignments/4/reset',
            'POST /api/v1/assignments/4/pretest',
            'POST /api/v1/assignments/4/handin',
            'GET /api/v1/assignments/4/handins',
            'GET /api/v1/assignments/4/handins?student=2',
            'GET /api/v1/assignments/4/dashboard',
            'GET /api/v1/assignments/4/overlay?variable=Mass%23P1%23x&points=200',
            'GET /api/v1/handins/7',
            'GET /api/v1/handins/7/comments',
            'POST /api/v1/handins/7/comments',
            'PUT /api/v1/handins/7/grade',
            'DELETE /api/v1/assignments/4',
            'DELETE /api/v1/classes/3',
        ]);
        const body = (i: number) => sent[i].body === undefined ? undefined : JSON.parse(sent[i].body!);
        expect(body(1)).toEqual({ name: 'Lab 1' });
        expect(body(3)).toEqual({ archived: true });
        expect(body(4)).toEqual({ code: 'ABCDEFGHJKLM' });
        expect(sent[5].headers['Content-Type']).toBe('text/csv');
        expect(sent[5].body).toBe('username\nx\ny\n');
        expect(body(6)).toEqual({ role: 'assistant' });
        expect(sent[8].headers.Accept).toBe('text/csv');
        expect(body(10)).toEqual({ title: 'T', template_model_id: 12, edit_mode: 'parameters', parameters: [{ name: 'P.k', min: 0, max: 100 }] });
        expect(body(13)).toEqual({ checks: [{ name: 'c', points: 2, pretest: true, definition: { kind: 'curve', variable: 'Mass#P1#x', tolerance: 0.05 } }] });
        expect(body(25)).toEqual({ text: 'Well done' });
        expect(body(26)).toEqual({ grade: null });
        expect(sent.every((s) => s.headers.Authorization === 'Bearer tok')).toBe(true);
    });

    it('gives the server\'s error code and message', async () => {
        const { labs } = fake(() => ({ status: 429, body: { error: { code: 'rate_limited', message: 'too many wrong codes: try again later' } } }));
        const error = await labs.join('WRONG').catch((e: unknown) => e);
        expect(error).toBeInstanceOf(ApiError);
        expect((error as ApiError).code).toBe('rate_limited');
        expect((error as ApiError).status).toBe(429);
        expect((error as ApiError).message).toBe('too many wrong codes: try again later');
    });

    it('asks again where a pretest answered 202 until its run has been judged', async () => {
        const pending = { job_id: 31, state: 'queued', location: '/api/v1/assignments/4/pretests/31' };
        const outcome = { checks: [{ name: 'c', passed: true }], score: 2, max_score: 2, job_id: 31 };
        const replies = [{ status: 202, body: pending }, { status: 202, body: { ...pending, state: 'running' } },
            { body: outcome }];
        const { labs, sent } = fake(() => replies.shift()!);
        const seen: string[] = [];
        expect(await labs.pretest(4, (state) => seen.push(state), 0)).toEqual(outcome);
        expect(seen).toEqual(['queued', 'running']);
        expect(sent.map((s) => `${s.method} ${s.url}`)).toEqual([
            'POST /api/v1/assignments/4/pretest', 'GET /api/v1/assignments/4/pretests/31',
            'GET /api/v1/assignments/4/pretests/31']);
    });

    it('lists the live sessions a teacher shares with the class', async () => {
        const shared = { session_id: 3, model_name: 'Servo demo', teacher: { id: 2, username: 'tina' } };
        const { labs, sent } = fake(() => ({ body: { sessions: [shared] } }));
        expect(await labs.sharedLiveSessions(5)).toEqual([shared]);
        expect(sent.map((s) => `${s.method} ${s.url}`)).toEqual(['GET /api/v1/classes/5/live']);
    });
});
