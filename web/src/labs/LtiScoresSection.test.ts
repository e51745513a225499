// @vitest-environment jsdom
// The scores sent to learning platforms, on an assignment's page for its staff: hidden while
// there are none or the server has no such route, else a row per score with its state, the
// attempts, the next attempt of a pending one and the last error; Refresh loads them again.
import { describe, expect, it, vi } from 'vitest';
import { ApiError } from '../api/ApiError';
import { ltiScoresSection } from './LtiScoresSection';
import type { LabClient } from './LabClient';
import type { LtiScoreInfo } from '../protocol/types';

const settle = async () => { for (let i = 0; i < 3; ++i) await new Promise((resolve) => setTimeout(resolve, 0)); };

const score = (id: number, change: Partial<LtiScoreInfo>): LtiScoreInfo => ({
    id, platform: 'Moodle of the faculty', user: { id: 9, username: 'ada' }, score_given: 8, score_maximum: 10,
    state: 'delivered', attempts: 1, next_attempt_at: 0, last_error: '', created_at: 1765000000, delivered_at: 1765000010, ...change,
});

const SCORES: LtiScoreInfo[] = [
    score(14, { state: 'pending', attempts: 2, next_attempt_at: 1765000040, last_error: 'the platform answered 503', delivered_at: 0 }),
    score(13, { user: { id: 10, username: 'bob' }, score_given: 2.5, score_maximum: 3 }),
    score(12, { state: 'superseded', attempts: 0, delivered_at: 0 }),
    score(11, { user: { id: 10, username: 'bob' }, state: 'failed', attempts: 10, last_error: 'the platform refused the token (401)', delivered_at: 0 }),
];

async function open(replies: (() => Promise<LtiScoreInfo[]>)[]) {
    const ltiScores = vi.fn();
    for (const reply of replies) ltiScores.mockImplementationOnce(reply);
    const element = ltiScoresSection({ ltiScores } as unknown as LabClient, 5);
    document.body.replaceChildren(element);
    await settle();
    return { element, ltiScores };
}

const rows = (element: HTMLElement) => [...element.querySelectorAll<HTMLTableRowElement>('[data-testid="lti-scores-table"] tbody tr')];
const cells = (row: HTMLTableRowElement) => [...row.querySelectorAll('td')].map((td) => td.textContent);

describe('grades sent to learning platforms', () => {
    it('stays hidden while no score was sent', async () => {
        const { element, ltiScores } = await open([async () => []]);
        expect(ltiScores).toHaveBeenCalledWith(5);
        expect(element.hidden).toBe(true);
    });

    it('stays hidden when the server has no such route (404) or refuses it (403)', async () => {
        for (const status of [404, 403]) {
            const { element } = await open([async () => { throw new ApiError(status === 404 ? 'not_found' : 'forbidden', 'no', status); }]);
            expect(element.hidden, String(status)).toBe(true);
        }
    });

    it('shows each score with its student, score, platform, state and times', async () => {
        const { element } = await open([async () => SCORES]);
        expect(element.hidden).toBe(false);
        expect(element.querySelector('h2')!.textContent).toBe('Grades sent to learning platforms');
        const shown = rows(element);
        expect(shown.map((r) => r.dataset.score)).toEqual(['14', '13', '12', '11']);
        expect(cells(shown[1]).slice(0, 3)).toEqual(['bob', '2.5 / 3', 'Moodle of the faculty']);
        expect(cells(shown[1])[5]).not.toBe('—');
        expect(cells(shown[0])[5]).toBe('—');
        const states = shown.map((r) => r.querySelector<HTMLElement>('[data-testid="lti-score-state"]')!);
        expect(states.map((s) => s.dataset.state)).toEqual(['pending', 'delivered', 'superseded', 'failed']);
        expect(states[0].textContent).toMatch(/^pending 2 attempts, next .+the platform answered 503$/);
        expect(states[1].textContent).toBe('delivered 1 attempt');
        expect(states[2].textContent).toBe('superseded not sent');
        expect(states[3].textContent).toBe('failed 10 attemptsthe platform refused the token (401)');
        expect(states[3].querySelector('.badge.lti-state-failed')).not.toBeNull();
        expect(states[1].querySelector('[data-testid="lti-score-error"]')).toBeNull();
    });

    it('loads the scores again on Refresh', async () => {
        const { element, ltiScores } = await open([async () => SCORES.slice(0, 1), async () => SCORES]);
        expect(rows(element)).toHaveLength(1);
        element.querySelector<HTMLButtonElement>('[data-testid="refresh-lti-scores"]')!.click();
        await settle();
        expect(ltiScores).toHaveBeenCalledTimes(2);
        expect(rows(element)).toHaveLength(4);
    });

    it('says why when the scores cannot be read for another reason', async () => {
        const { element } = await open([async () => { throw new ApiError('internal', 'the database is busy', 500); }]);
        expect(element.hidden).toBe(false);
        expect(element.querySelector('[role="alert"]')!.textContent).toContain('the database is busy');
    });
});
