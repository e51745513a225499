// @vitest-environment jsdom
// A followed study advanced by event.study.progress, and what the panel shows of it.
import { describe, expect, it, vi } from 'vitest';

// uPlot asks for the pixel ratio's media query when it is loaded; jsdom has none
vi.hoisted(() => {
    window.matchMedia = (() => ({ addEventListener: () => undefined, removeEventListener: () => undefined })) as unknown as typeof window.matchMedia;
});

import { applyProgress, progressText, type FollowedStudy } from './studyProgress';
import { StudyDetailView } from './StudyDetailView';
import type { StudyInfo, StudyProgressEvent } from './studyTypes';

const info: StudyInfo = {
    id: 7, kind: 'sweep', name: '', model_id: 3, state: 'running', runs_total: 4, runs_done: 1, runs_failed: 0, progress: 0.25,
    error: '', created_at: 1, started_at: 1, finished_at: null, summary: {},
};
const columns = ['run', 'ok', 'Divide.in2', 'Divide#out#Value:final'];
const study: FollowedStudy = { info, table: { columns, rows: [[0, 1, 1, 5]], errors: {} } };
const event = (fields: Partial<StudyProgressEvent>): StudyProgressEvent => ({
    type: 'event.study.progress', study_id: 7, state: 'running', runs_done: 1, runs_failed: 0, runs_total: 4, columns, rows: [], ...fields,
});

describe('a followed study', () => {
    it('takes the rows, counts and failure reasons of each event', () => {
        const next = applyProgress(study, event({
            runs_done: 2, runs_failed: 1, rows: [[2, 0, 0, null], [1, 1, 2, 2.5]],
            failure_reasons: [{ message: 'Divide: Division by zero', count: 1, first_run: 2 }],
        }));
        expect(next.table.rows.map((r) => r[0])).toEqual([0, 1, 2]);
        expect(next.info).toMatchObject({ runs_done: 2, runs_failed: 1, progress: 0.75 });
        expect(next.info.summary.failure_reasons).toEqual([{ message: 'Divide: Division by zero', count: 1, first_run: 2 }]);
        expect(progressText(next.info)).toBe('running: 3 of 4 runs, 1 failed');
    });

    it('ignores another study\'s events and keeps the final state and error', () => {
        expect(applyProgress(study, event({ study_id: 8, runs_done: 4 }))).toBe(study);
        const ended = applyProgress(study, event({ state: 'failed', error: 'all 4 runs failed' }));
        expect(ended.info).toMatchObject({ state: 'failed', error: 'all 4 runs failed' });
    });

    it('the panel shows the runs done and failed, why they failed, and Cancel while it runs', () => {
        const view = new StudyDetailView({
            cancel: () => undefined, resume: () => undefined, remove: () => undefined, downloadCsv: () => undefined,
            applyBest: () => undefined, bands: () => new Promise(() => undefined), goal: () => undefined,
        });
        // (a running sensitivity study: no chart yet, which jsdom could not draw)
        view.show(applyProgress({ ...study, info: { ...info, kind: 'sensitivity' } }, event({
            runs_done: 2, runs_failed: 2, rows: [[1, 0, 0, null], [2, 0, 0, null]],
            failure_reasons: [{ message: 'Divide: Division by zero', count: 2, first_run: 1 }],
        })));
        const el = view.element;
        expect(el.querySelector('[data-testid="study-progress"]')?.getAttribute('data-failed')).toBe('2');
        expect(el.querySelector('[data-testid="study-failures"]')?.textContent).toContain('Divide: Division by zero — 2 runs, first run 1');
        const button = (id: string) => el.querySelector<HTMLButtonElement>(`[data-testid="${id}"]`)!;
        expect(button('study-cancel').hidden).toBe(false);
        expect(button('study-resume').hidden).toBe(true);
        expect(button('study-delete').hidden).toBe(true);
        expect(el.querySelector<HTMLElement>('[data-testid="study-best"]')!.hidden).toBe(true);
        expect(el.querySelector('[data-testid="study-results-table"]')?.getAttribute('data-rows')).toBe('3');
        expect(el.querySelector('[data-testid="study-bands"]')?.textContent).toBe('The bands are drawn once the study has finished.');
        // the next event updates the same buttons (a click on one is not lost to a redraw)
        const cancel = button('study-cancel');
        view.show(applyProgress({ ...study, info: { ...info, kind: 'sensitivity' } }, event({ state: 'cancelled', runs_done: 3 })));
        expect(button('study-cancel')).toBe(cancel);
        expect(cancel.hidden).toBe(true);
        expect(button('study-resume').hidden).toBe(false);
        view.dispose();
    });
});
