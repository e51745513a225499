// @vitest-environment jsdom
// The run status says what became of the last attempt to run: a run the server refused names
// the server's reason, and keeps naming it until the next run starts.
import { describe, expect, it, vi } from 'vitest';
import { RunController } from './RunController';
import { RunPanel } from './RunPanel';
import type { PlotArea } from './PlotArea';
import { ApiError } from '../api/ApiError';
import type { ServerEvent } from '../protocol/types';

const settings = { start: 0, step: 0.001, stop: 1, log_samples: 0 };
const refusal = new ApiError('limit_exceeded', 'the job needs 1e+12 steps; the limit is 50000000 (--max-steps)', 0);

function panelWithRuns() {
    let listener: ((e: ServerEvent) => void) | null = null;
    let nextJob = 10;
    const answer = vi.fn(async (): Promise<{ job_id: number }> => ({ job_id: nextJob++ }));
    const runs = new RunController({
        request: (async (type: string) => (type === 'simulate.start' ? answer() : {})) as never,
        onEvent: (l: (e: ServerEvent) => void) => { listener = l; return () => { listener = null; }; },
        resultsJson: async () => ({ time: [], variables: [] }),
    });
    const plots = { allVariables: () => [], addVariable: () => undefined } as unknown as PlotArea;
    const panel = new RunPanel(runs, plots, settings, () => []);
    const status = panel.element.querySelector<HTMLElement>('[data-testid="run-status"]')!;
    return { runs, panel, status, answer, emit: (e: ServerEvent) => listener?.(e) };
}

describe('RunPanel', () => {
    it('a refused run shows the server\'s reason until the next run starts', async () => {
        const t = panelWithRuns();
        await t.panel.start();
        t.emit({ type: 'event.done', job_id: 10, state: 'done' });
        expect(t.status.textContent).toBe('Job 10: done');

        t.answer.mockRejectedValueOnce(refusal);
        await t.panel.start();
        expect(t.status.textContent).toBe(`Not started: ${refusal.message}`);
        expect(t.status.dataset.state).toBe('not-started');
        expect(t.status.dataset.job).toBeUndefined();
        // news of the earlier run (its results loaded, say) does not bring it back
        await t.runs.ensure([]);
        expect(t.status.textContent).toBe(`Not started: ${refusal.message}`);

        await t.panel.start();
        expect(t.status.textContent).toBe('Job 11: running 0%');
        expect(t.status.dataset.state).toBe('running');
    });

    it('a run that ended as the model meant shows done with the reason', async () => {
        const t = panelWithRuns();
        await t.panel.start();
        t.emit({ type: 'event.done', job_id: 10, state: 'done', stop_reason: 'Simulation stopped by Stop_simulation' });
        expect(t.status.textContent).toBe('Job 10: done — Simulation stopped by Stop_simulation');
        expect(t.status.dataset.state).toBe('done');
    });
});
