// The model's run history beside the plots, newest first: each run's name (the user may name
// and pin it), when, who, what became of it and what it simulated. Hovering a run lists the
// parameters it used otherwise than the latest run; clicking it shows it in the plot windows.
import type { JobInfo } from '../protocol/types';
import type { RestClient } from '../api/RestClient';
import { isChoosable, runLabel, type RunController } from './RunController';
import { differencesFromLatest, differencesText } from './runDifferences';
import { spanText, stateText, whenText } from './historyRow';
import { h, errorText, toast } from '../ui/dom';
import './historyPanel.css';

/** How many runs a page of the history lists. */
export const HISTORY_PANEL_PAGE = 20;
/** The most runs the server lists at once (reloading all the pages shown). */
const MAX_PAGE = 100;

export interface HistoryPanelOptions {
    modelId: () => number;
    /** The logged-in user's name: only a run's owner may name or pin it. */
    username: () => string | undefined;
    /** The model's parameter value texts by path, as the editor holds them (parameterTexts). */
    parameters: () => Map<string, string>;
    /** The variables the plot windows show: a chosen run's results for them are loaded. */
    plotted: () => string[];
    /** Plays the run back on the animated diagram; absent: runs have no play button. */
    playBack?: (job: JobInfo) => void;
}

type HistoryRest = Pick<RestClient, 'runHistory' | 'labelJob'>;

export class HistoryPanel {
    readonly element: HTMLElement;
    private readonly list: HTMLElement;
    private readonly moreButton: HTMLButtonElement;
    private readonly note: HTMLElement;
    private readonly count: HTMLElement;
    private jobs: JobInfo[] = [];
    /** Each load gets a number: an answer that comes after a newer load's is dropped. */
    private loads = 0;
    /** The current run and its state when last looked at: a change (a run started or ended) reloads. */
    private seenRun = '';
    private shownJob: number | null = null;
    private readonly unsubscribe: () => void;

    constructor(private readonly rest: HistoryRest, private readonly runs: RunController, private readonly options: HistoryPanelOptions) {
        this.list = h('ul', { class: 'history-list', 'aria-label': 'Runs of the model' });
        this.moreButton = h('button', { class: 'small history-more', hidden: true, onclick: () => void this.loadMore() }, 'More');
        this.note = h('p', { class: 'history-note muted' }, 'Loading runs…');
        this.count = h('span', { class: 'history-count muted' });
        this.element = h('aside', { class: 'history-panel', 'aria-label': 'Run history' },
            h('header', { class: 'history-header', title: 'Click a run to plot it; hover it for the parameters it used otherwise than the latest run' },
                h('span', {}, 'Runs'), this.count),
            this.list, this.note, this.moreButton);
        this.unsubscribe = runs.subscribe(() => this.onRuns());
        void this.reload();
    }

    dispose(): void { this.unsubscribe(); }

    /** Lists the newest runs again, as many as are shown (a run started or ended). */
    async reload(): Promise<void> {
        const load = ++this.loads;
        const limit = Math.min(Math.max(this.jobs.length, HISTORY_PANEL_PAGE), MAX_PAGE);
        try {
            const jobs = await this.rest.runHistory(this.options.modelId(), limit);
            if (load !== this.loads) return;
            this.show(jobs, jobs.length === limit);
        } catch (e) {
            if (load === this.loads) this.note.textContent = `Runs: ${errorText(e)}`;
        }
    }

    private async loadMore(): Promise<void> {
        const last = this.jobs.at(-1);
        if (!last) return;
        const load = ++this.loads;
        this.moreButton.disabled = true;
        try {
            const page = await this.rest.runHistory(this.options.modelId(), HISTORY_PANEL_PAGE, last.id);
            if (load !== this.loads) return;
            this.show([...this.jobs, ...page], page.length === HISTORY_PANEL_PAGE);
        } catch (e) {
            toast(`Runs: ${errorText(e)}`, 'error');
        } finally {
            this.moreButton.disabled = false;
        }
    }

    private onRuns(): void {
        const current = this.runs.current;
        const seen = current ? `${current.jobId}:${current.state}` : '';
        if (seen !== this.seenRun) {
            this.seenRun = seen;
            // (a run restored from the history is listed as it is)
            const listed = current === null || this.jobs.some((j) => j.id === current.jobId && j.state === current.state);
            if (!listed) void this.reload();
        }
        const shown = this.shownRun();
        if (shown !== this.shownJob) {
            this.shownJob = shown;
            for (const row of this.list.children) this.markShown(row as HTMLElement);
        }
    }

    private show(jobs: JobInfo[], more: boolean): void {
        this.jobs = jobs;
        this.moreButton.hidden = !more;
        this.count.textContent = jobs.length > 0 ? `${jobs.length}${more ? '+' : ''}` : '';
        this.note.hidden = jobs.length > 0;
        this.note.textContent = 'No runs yet: ▶ Run simulates the model.';
        const parameters = this.options.parameters();
        const now = new Date();
        this.list.replaceChildren(...jobs.map((job) => this.row(job, parameters, now)));
    }

    private row(job: JobInfo, parameters: Map<string, string>, now: Date): HTMLElement {
        const latest = this.jobs[0];
        const label = runLabel(job);
        const at = job.finished_at ?? job.created_at;
        const differences = job.id === latest.id ? 'The latest run' : differencesText(differencesFromLatest(job, latest, (p) => parameters.get(p)));
        const descriptionId = `history-differences-${job.id}`;
        const choosable = isChoosable(job);
        const own = job.owner === undefined || job.owner === this.options.username();
        const state = job.results_dropped ? `${stateText(job)}, results dropped` : stateText(job);
        const show = h('button', {
            class: 'history-show', 'aria-describedby': descriptionId,
            'aria-disabled': choosable ? undefined : 'true',
            onclick: () => { if (choosable) this.choose(job); },
            ondblclick: () => { if (own) this.rename(row, job); },
        },
        h('span', { class: 'history-label' }, label),
        h('span', { class: 'history-when' }, whenText(at, now)),
        h('span', { class: 'history-meta' },
            h('span', { class: `history-state state-${job.state}` }, state),
            ` · ${spanText(job)}`,
            own ? '' : h('span', { class: 'history-owner' }, ` · ${job.owner}`)));
        const pin = h('button', {
            class: 'history-pin', 'aria-pressed': String(job.pinned), 'aria-label': `Pin ${label}`,
            title: own ? (job.pinned ? 'Pinned: its results are kept. Click to unpin' : 'Pin: keep its results however many runs follow') : `Only ${job.owner} can pin it`,
            disabled: !own, onclick: () => void this.label(job, { pinned: !job.pinned }),
        }, job.pinned ? '★' : '☆');
        const renameButton = h('button', {
            class: 'history-rename', 'aria-label': `Rename ${label}`, title: 'Name the run', hidden: !own,
            onclick: () => this.rename(row, job),
        }, '✎');
        const playBack = this.options.playBack;
        const play = playBack ? h('button', {
            class: 'history-play', 'aria-label': `Play back ${label}`, 'data-testid': 'history-play',
            title: job.state === 'done' ? 'Play back: the run on the animated diagram, with a cursor in the plots' : 'Only a finished run can be played back',
            disabled: job.state !== 'done' || job.results_dropped, onclick: () => playBack(job),
        }, '▶') : null;
        const row = h('li', {
            class: 'history-row', 'data-job': String(job.id), 'data-state': job.state,
            title: `${label} — ${new Date(at * 1000).toLocaleString()}${choosable ? '' : ' (cannot be plotted)'}\n${differences}`,
        },
        pin, show, renameButton, play,
        h('span', { id: descriptionId, hidden: true }, differences));
        row.classList.toggle('unavailable', !choosable);
        this.markShown(row);
        return row;
    }

    /** The run the plot windows show, unless one stepped elsewhere: the chosen one, else the newest. */
    private shownRun(): number | null {
        return (this.runs.chosen ?? this.runs.generations.at(-1))?.jobId ?? null;
    }

    /** The run the plot windows show stands out. */
    private markShown(row: HTMLElement): void {
        const shown = row.dataset.job === String(this.shownRun());
        row.classList.toggle('shown', shown);
        if (shown) row.setAttribute('aria-current', 'true');
        else row.removeAttribute('aria-current');
    }

    private choose(job: JobInfo): void {
        this.runs.choose(job, this.options.plotted()).catch((e) => toast(`Results: ${errorText(e)}`, 'error'));
    }

    /**
     * The name becomes an input: Enter saves it (a refusal is shown beside it), Esc leaves it,
     * as does leaving the input unchanged.
     */
    private rename(row: HTMLElement, job: JobInfo): void {
        const show = row.querySelector('.history-show');
        if (!show) return;   // already being renamed
        const error = h('span', { class: 'field-error', role: 'alert' });
        const input = h('input', {
            class: 'history-name', value: job.name, placeholder: `run ${job.id}`, 'aria-label': `Name of run ${job.id}`, maxlength: 200,
            onkeydown: (e: KeyboardEvent) => {
                if (e.key === 'Escape') this.replaceRow(row, job);
                if (e.key !== 'Enter') return;
                e.preventDefault();
                this.rest.labelJob(job.id, { name: input.value.trim() }).then((renamed) => {
                    this.replaceRow(row, renamed);
                    this.runs.rename(renamed);
                }, (e: unknown) => { error.textContent = errorText(e); });
            },
            onblur: () => { if (input.value === job.name && row.parentElement === this.list) this.replaceRow(row, job); },
        });
        show.replaceWith(h('div', { class: 'history-edit' }, input, error));
        input.focus();
        input.select();
    }

    private async label(job: JobInfo, change: { pinned: boolean }): Promise<void> {
        const row = this.list.querySelector<HTMLElement>(`[data-job="${job.id}"]`);
        try {
            const changed = await this.rest.labelJob(job.id, change);
            if (row) this.replaceRow(row, changed);
        } catch (e) {
            toast(`Run ${job.id}: ${errorText(e)}`, 'error');
        }
    }

    /** Draws a run's row again with what the server answered (history fields stay as listed). */
    private replaceRow(row: HTMLElement, job: JobInfo): void {
        const i = this.jobs.findIndex((j) => j.id === job.id);
        if (i < 0) return;
        const listed = this.jobs[i];
        this.jobs[i] = { ...listed, name: job.name, pinned: job.pinned, results_dropped: job.results_dropped };
        row.replaceWith(this.row(this.jobs[i], this.options.parameters(), new Date()));
    }
}
