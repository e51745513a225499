// @vitest-environment jsdom
// The run history beside the plots: its rows, naming and pinning a run, a run shown in the
// plots when clicked, and the list kept up to date as runs end.
import { describe, expect, it, vi } from 'vitest';
import { HistoryPanel, HISTORY_PANEL_PAGE } from './HistoryPanel';
import { RunController } from './RunController';
import { ApiError } from '../api/ApiError';
import type { JobInfo, ServerEvent } from '../protocol/types';

const job = (id: number, more: Partial<JobInfo> = {}): JobInfo => ({
    id, model_id: 4, state: 'done', progress: 1, error: '', created_at: 1000, started_at: 1000, finished_at: 1001, steps: 3000,
    settings: { start: 0, step: 0.001, stop: 3, log_samples: 0 }, name: '', pinned: false, results_dropped: false,
    owner: 'hana', parameters: {}, differing_parameters: {}, ...more,
});

function panelOf(history: JobInfo[]) {
    let listener: ((e: ServerEvent) => void) | null = null;
    const runs = new RunController({
        request: (async () => ({ job_id: 20 })) as never,
        onEvent: (l: (e: ServerEvent) => void) => { listener = l; return () => { listener = null; }; },
        resultsJson: async (_id: number, names: string[]) => ({ time: [0, 1], variables: names.map((name) => ({ name, unit: '', data: [1, 2] })) }),
    });
    const rest = {
        runHistory: vi.fn(async (_model: number, limit = 20, before?: number) =>
            history.filter((j) => before === undefined || j.id < before).slice(0, limit)),
        labelJob: vi.fn(async (id: number, change: { name?: string; pinned?: boolean }) => {
            const i = history.findIndex((j) => j.id === id);
            history[i] = { ...history[i], ...change };
            return history[i];
        }),
    };
    const panel = new HistoryPanel(rest, runs, {
        modelId: () => 4, username: () => 'hana',
        parameters: () => new Map([['GainP.k#Value', '0.0264249']]),
        plotted: () => ['Mass#P2#Position'],
    });
    const row = (id: number) => panel.element.querySelector<HTMLElement>(`.history-row[data-job="${id}"]`)!;
    const texts = () => [...panel.element.querySelectorAll('.history-label')].map((e) => e.textContent);
    return { panel, runs, rest, row, texts, emit: (e: ServerEvent) => listener?.(e) };
}

const settle = () => new Promise((r) => setTimeout(r, 0));

describe('HistoryPanel', () => {
    it('lists the runs newest first: name or job, what became of them, and who ran them when not the user', async () => {
        const { panel, texts, row } = panelOf([
            job(9, { name: 'stiffer', pinned: true }),
            job(8, { state: 'failed', error: 'diverged at 1.2 s' }),
            job(7, { stop_reason: 'Simulation stopped by Stop' }),
            job(6, { owner: 'teacher' }),
        ]);
        await settle();
        expect(texts()).toEqual(['stiffer', 'run 8', 'run 7', 'run 6']);
        expect(row(9).querySelector('.history-pin')?.getAttribute('aria-pressed')).toBe('true');
        expect(row(9).querySelector('.history-pin')?.textContent).toBe('★');
        expect(row(8).querySelector('.history-meta')?.textContent).toBe('failed: diverged at 1.2 s · 0–3 s, 3000 steps');
        expect(row(7).querySelector('.history-state')?.textContent).toBe('ended by model: Simulation stopped by Stop');
        expect(row(6).querySelector('.history-owner')?.textContent).toBe(' · teacher');
        expect(row(9).querySelector('.history-owner')).toBeNull();
        // another user's run: not the user's to pin or name
        expect(row(6).querySelector<HTMLButtonElement>('.history-pin')?.disabled).toBe(true);
        expect(row(6).querySelector<HTMLButtonElement>('.history-rename')?.hidden).toBe(true);
        expect(panel.element.querySelector<HTMLButtonElement>('.history-more')?.hidden).toBe(true);
    });

    it('a row\'s hover text and description name the parameters it used otherwise than the latest run', async () => {
        const { row } = panelOf([job(9), job(8, { differing_parameters: { 'GainP.k#Value': '0.02' } })]);
        await settle();
        expect(row(8).title).toMatch(/\nDiffers from the latest run in:\nGainP\.k: 0\.02 \(latest 0\.0264249\)$/);
        const described = row(8).querySelector('.history-show')!.getAttribute('aria-describedby')!;
        expect(row(8).querySelector(`#${described}`)?.textContent).toContain('GainP.k: 0.02 (latest 0.0264249)');
        expect(row(9).title).toMatch(/\nThe latest run$/);
    });

    it('pins a run and names it: Enter saves, a refusal is shown beside the name, Esc leaves it', async () => {
        const { rest, row, texts } = panelOf([job(9), job(8)]);
        await settle();
        row(8).querySelector<HTMLButtonElement>('.history-pin')!.click();
        await settle();
        expect(rest.labelJob).toHaveBeenCalledWith(8, { pinned: true });
        expect(row(8).querySelector('.history-pin')?.getAttribute('aria-pressed')).toBe('true');

        row(8).querySelector<HTMLButtonElement>('.history-rename')!.click();
        const input = row(8).querySelector<HTMLInputElement>('input.history-name')!;
        input.value = 'baseline';
        input.dispatchEvent(new KeyboardEvent('keydown', { key: 'Enter' }));
        await settle();
        expect(rest.labelJob).toHaveBeenLastCalledWith(8, { name: 'baseline' });
        expect(texts()).toEqual(['run 9', 'baseline']);
        expect(row(8).querySelector('.history-pin')?.getAttribute('aria-pressed')).toBe('true');

        rest.labelJob.mockRejectedValueOnce(new ApiError('bad_request', 'name: at most 200 characters', 400));
        row(9).querySelector<HTMLElement>('.history-show')!.dispatchEvent(new MouseEvent('dblclick'));
        const refused = row(9).querySelector<HTMLInputElement>('input.history-name')!;
        refused.value = 'x'.repeat(300);
        refused.dispatchEvent(new KeyboardEvent('keydown', { key: 'Enter' }));
        await settle();
        expect(row(9).querySelector('.history-edit .field-error')?.textContent).toBe('name: at most 200 characters');
        refused.dispatchEvent(new KeyboardEvent('keydown', { key: 'Escape' }));
        expect(texts()).toEqual(['run 9', 'baseline']);

        // leaving the input unchanged leaves the name as it was
        row(8).querySelector<HTMLButtonElement>('.history-rename')!.click();
        row(8).querySelector('input.history-name')!.dispatchEvent(new FocusEvent('blur'));
        expect(texts()).toEqual(['run 9', 'baseline']);
        expect(rest.labelJob).toHaveBeenCalledTimes(3);   // the pin, the name, the refused name
    });

    it('a clicked run is shown in the plots, with the results of the plotted variables; one whose results were dropped is not', async () => {
        const { runs, row } = panelOf([job(9), job(8), job(7, { results_dropped: true })]);
        runs.restore([job(9), job(8)]);
        await settle();
        expect(row(9).getAttribute('aria-current')).toBe('true');
        row(8).querySelector<HTMLElement>('.history-show')!.click();
        await settle();
        expect(runs.chosen?.jobId).toBe(8);
        expect(runs.chosen?.columns.get('Mass#P2#Position')).toEqual([1, 2]);
        expect(row(8).getAttribute('aria-current')).toBe('true');
        expect(row(9).hasAttribute('aria-current')).toBe(false);

        expect(row(7).querySelector('.history-state')?.textContent).toBe('done, results dropped');
        expect(row(7).querySelector('.history-show')?.getAttribute('aria-disabled')).toBe('true');
        row(7).querySelector<HTMLElement>('.history-show')!.click();
        await settle();
        expect(runs.chosen?.jobId).toBe(8);
    });

    it('loads older runs with More, and lists the runs again when one ends', async () => {
        const history = Array.from({ length: HISTORY_PANEL_PAGE + 3 }, (_, i) => job(100 - i));
        const { panel, rest, runs, texts, emit } = panelOf(history);
        await settle();
        expect(texts()).toHaveLength(HISTORY_PANEL_PAGE);
        const more = panel.element.querySelector<HTMLButtonElement>('.history-more')!;
        expect(more.hidden).toBe(false);
        more.click();
        await settle();
        expect(rest.runHistory).toHaveBeenLastCalledWith(4, HISTORY_PANEL_PAGE, 81);
        expect(texts()).toHaveLength(HISTORY_PANEL_PAGE + 3);
        expect(more.hidden).toBe(true);

        await runs.start({}, []);
        history.unshift(job(101, { state: 'running' }));
        await settle();
        history[0] = job(101);
        emit({ type: 'event.done', job_id: 20, state: 'done' });
        await settle();
        // as many runs as were shown, the new one first
        expect(rest.runHistory).toHaveBeenLastCalledWith(4, HISTORY_PANEL_PAGE + 3);
        expect(texts()[0]).toBe('run 101');
        expect(texts()).toHaveLength(HISTORY_PANEL_PAGE + 3);
    });
});
