// @vitest-environment jsdom
// A hand-in's details: comments are plain text (never HTML), the outcomes table says what
// passed, and staff controls appear only for staff and not in an archived class.
import { describe, expect, it } from 'vitest';
import { RestClient } from '../api/RestClient';
import { LabClient } from './LabClient';
import { handInDetails, outcomesTable } from './HandInDetails';
import type { Session } from '../app/Session';
import type { HandIn } from './types';

const handIn: HandIn = {
    id: 11, assignment_id: 5, student: { id: 3, username: 'stan' }, attempt: 2, handed_in_at: 1764700000, late: true,
    score: 1, max_score: 3, grade: null, job_id: 4,
    checks: [
        { name: 'Curve', pretest: true, passed: true, points: 2, awarded: 2, deviation: 0.012, worst_time: 1.5, message: '' },
        { name: 'Final', pretest: false, passed: false, points: 1, awarded: 0, value: 0.9, message: 'above the max 0.75' },
    ],
};

function session(comments: unknown[]): Session {
    const fetchFn = (async () => new Response(JSON.stringify({ comments }), { status: 200 })) as unknown as typeof fetch;
    const rest = new RestClient('t', '/api/v1', fetchFn);
    return { rest, labs: new LabClient(rest) } as unknown as Session;
}

const tick = () => new Promise((r) => setTimeout(r, 0));

describe('hand-in details', () => {
    it('shows a comment as text, never as HTML', async () => {
        const el = handInDetails(session([{ id: 1, author: { id: 2, username: 'tina' }, text: '<img src=x onerror=alert(1)><script>alert(2)</script>', created_at: 1764700100 }]),
            handIn, { canComment: false, canGrade: false, archived: false });
        await tick();
        await tick();
        const comment = el.querySelector('.comment-text')!;
        expect(comment.textContent).toBe('<img src=x onerror=alert(1)><script>alert(2)</script>');
        expect(el.querySelector('img, script')).toBeNull();
        expect(el.textContent).toContain('tina');
    });

    it('offers comment and grade forms to the staff, not in an archived class', () => {
        const student = handInDetails(session([]), handIn, { canComment: false, canGrade: false, archived: false });
        expect(student.querySelector('.comment-form, .grade-form')).toBeNull();
        const teacher = handInDetails(session([]), handIn, { canComment: true, canGrade: true, archived: false });
        expect(teacher.querySelector('.comment-form')).not.toBeNull();
        expect(teacher.querySelector('.grade-form')).not.toBeNull();
        const archived = handInDetails(session([]), handIn, { canComment: true, canGrade: true, archived: true });
        expect(archived.querySelector('.comment-form, .grade-form')).toBeNull();
        expect(teacher.querySelector('header')?.textContent).toMatch(/Attempt 2.*late.*score 1 \/ 3/);
    });

    it('tables outcomes with passed, points, value or deviation and message', () => {
        const table = outcomesTable(handIn.checks!);
        const rows = [...table.querySelectorAll('tbody tr')].map((tr) => [...tr.querySelectorAll('td')].map((td) => td.textContent));
        expect(rows).toEqual([
            ['Curvepretest', '✓ passed', '2 / 2', 'deviation 1.2 %, at t = 1.5 s', ''],
            ['Final', '✗ failed', '0 / 1', 'value 0.9', 'above the max 0.75'],
        ]);
    });
});
