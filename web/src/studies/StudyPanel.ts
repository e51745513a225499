// The study panel of the editor ("Study…"): the model's studies (from GET /studies, so they
// survive a reload), a form for a new one, and the chosen study followed live over the
// editor's socket (study.subscribe, subscribed again after a reconnect).
import { downloadText, errorText, h, toast } from '../ui/dom';
import './studies.css';
import type { RestClient } from '../api/RestClient';
import type { WsClient } from '../api/WsClient';
import type { EditorStore } from '../editor/EditorStore';
import type { ResultsJson } from '../protocol/types';
import { StudyClient } from './StudyClient';
import { StudyFormView } from './StudyFormView';
import { StudyDetailView } from './StudyDetailView';
import { defaultForm } from './studyForm';
import { studyParameters } from './studyParameters';
import { loggedVariables } from './studyVariables';
import { applyProgress, progressText, type FollowedStudy } from './studyProgress';
import { ApplyBestPoint } from './ApplyBestPoint';
import { mergeRows } from './studyTable';
import type { Goal } from './convergence';
import { FINAL_STATES, type StudyInfo, type StudyProgressEvent } from './studyTypes';

export interface StudyPanelContext {
    rest: Pick<RestClient, 'call' | 'resultsJson'>;
    ws: Pick<WsClient, 'request' | 'onEvent' | 'onReconnect'>;
    store: EditorStore;
    modelId(): number;
    /** The model's latest finished run (the objective preview is computed on it). */
    latestRun(): { jobId: number } | null;
}

const LIST_REFRESH_MS = 2000;
const POLL_MS = 1000;

export class StudyPanel {
    private readonly client: StudyClient;
    private readonly dialog = h('dialog', { class: 'study-dialog', 'data-testid': 'study-dialog', 'aria-label': 'Studies' });
    private readonly list = h('ul', { class: 'study-list', 'data-testid': 'study-list' });
    private readonly main = h('div', { class: 'study-main' });
    private readonly detail: StudyDetailView;
    private form: StudyFormView | null = null;
    private studies: StudyInfo[] = [];
    private followed: FollowedStudy | null = null;
    private subscribed: number | null = null;
    private readonly goals = new Map<number, Goal>();
    /**
     * Replies and events cross on the way (a read sent before Cancel answers after the study's
     * last event; a read sent before Resume answers after it). Each follow() of a study starts a
     * new epoch, and replies of an older one are dropped; within one, a study that has shown a
     * final state keeps it (only Resume, which follows it anew, takes it out of it).
     */
    private epoch = 0;
    private finalSeen = false;
    private listTimer: ReturnType<typeof setTimeout> | undefined;
    private readonly detach: (() => void)[] = [];

    constructor(private readonly ctx: StudyPanelContext) {
        this.client = new StudyClient(ctx.rest);
        this.detail = new StudyDetailView({
            cancel: (id) => void this.act(() => this.client.cancel(id)),
            resume: (id) => void this.act(async () => { await this.client.resume(id); await this.follow(id); }),
            remove: (id) => void this.act(async () => {
                await this.client.remove(id);
                if (this.followed?.info.id === id) this.showForm();
            }),
            downloadCsv: (info) => void this.act(async () => downloadText(`study-${info.id}.csv`, await this.client.tableCsv(info.id), 'text/csv')),
            applyBest: (info) => void this.applyBest(info),
            bands: (id) => this.client.bands(id),
            goal: (id) => this.goals.get(id),
        });
        this.dialog.append(
            h('header', { class: 'study-dialog-header' },
                h('h2', {}, 'Studies'),
                h('button', { type: 'button', 'data-testid': 'study-new', onclick: () => this.showForm() }, 'New study'),
                h('button', { type: 'button', class: 'study-close', 'aria-label': 'Close', 'data-testid': 'study-close', onclick: () => this.close() }, '✕')),
            h('div', { class: 'study-dialog-body' },
                h('aside', { class: 'study-aside' }, h('h3', {}, 'This model\'s studies'), this.list),
                this.main));
        // Escape closes the dialog as its button does (unsubscribing)
        this.dialog.addEventListener('cancel', (e) => { e.preventDefault(); this.close(); });
        this.detach.push(ctx.ws.onEvent((event) => {
            if ((event as { type: string }).type === 'event.study.progress') this.onProgress(event as unknown as StudyProgressEvent);
        }));
        // a new socket has no subscriptions: the followed study is subscribed again, its rows read again
        this.detach.push(ctx.ws.onReconnect(async () => {
            const id = this.subscribed;
            this.subscribed = null;
            if (id !== null && this.dialog.open) await this.follow(id);
        }));
    }

    get isOpen(): boolean { return this.dialog.open; }

    /** Opens the panel: the list from the server; the running study of the model, if any, followed. */
    async open(): Promise<void> {
        if (!this.dialog.isConnected) document.body.append(this.dialog);
        if (!this.dialog.open) this.dialog.showModal();
        await this.refreshList();
        const running = this.studies.find((s) => !FINAL_STATES.has(s.state));
        if (this.followed) await this.follow(this.followed.info.id);
        else if (running) await this.follow(running.id);
        else this.showForm();
    }

    close(): void {
        clearTimeout(this.listTimer);
        void this.unsubscribe();
        if (this.dialog.open) this.dialog.close();
    }

    dispose(): void {
        this.close();
        this.detail.dispose();
        for (const d of this.detach) d();
        this.dialog.remove();
    }

    private showForm(): void {
        this.detail.dispose();
        void this.unsubscribe();
        this.followed = null;
        this.form ??= new StudyFormView({
            parameters: () => studyParameters(this.ctx.store.model),
            variables: () => loggedVariables(this.ctx.store.model),
            latestRun: this.ctx.latestRun,
            results: (jobId: number, variables: string[]): Promise<ResultsJson> => this.ctx.rest.resultsJson(jobId, variables),
            unsaved: () => this.ctx.store.dirty,
            modelId: this.ctx.modelId,
            submit: async (form, request) => {
                const created = await this.client.submit(request);
                if (form.kind === 'optimise') this.goals.set(created.id, form.goal);
                await this.refreshList();
                await this.follow(created.id);
            },
        }, defaultForm());
        this.form.render();   // the model may have changed since the form was last shown
        this.main.replaceChildren(h('h3', {}, 'New study'), this.form.element);
        this.drawList();
    }

    private async refreshList(): Promise<void> {
        clearTimeout(this.listTimer);
        try {
            const all = await this.client.list();
            this.studies = all.filter((s) => s.model_id === this.ctx.modelId());
        } catch (e) {
            toast(`Studies: ${errorText(e)}`, 'error');
        }
        this.drawList();
        // other running studies of the list move on too
        if (this.dialog.open && this.studies.some((s) => !FINAL_STATES.has(s.state) && s.id !== this.subscribed)) {
            this.listTimer = setTimeout(() => void this.refreshList(), LIST_REFRESH_MS);
        }
    }

    private drawList(): void {
        const chosen = this.followed?.info.id;
        this.list.replaceChildren(...(this.studies.length === 0
            ? [h('li', { class: 'muted' }, 'None yet.')]
            : this.studies.map((s) => {
                const info = s.id === chosen && this.followed ? this.followed.info : s;
                return h('li', { 'data-study': String(s.id), 'data-state': info.state, class: s.id === chosen ? 'chosen' : '' },
                    h('button', { type: 'button', class: 'link-button', onclick: () => void this.follow(s.id) },
                        `${s.id}: ${info.kind}${info.name ? ` “${info.name}”` : ''}`),
                    h('div', { class: 'muted' }, progressText(info)));
            })));
    }

    /** Shows a study: its state and table from the server, then its events while it runs. */
    private async follow(id: number): Promise<void> {
        const epoch = ++this.epoch;
        this.finalSeen = false;
        await this.unsubscribe();
        try {
            const [info, table] = await Promise.all([this.client.get(id), this.client.table(id)]);
            if (epoch !== this.epoch) return;   // another study (or this one again) is followed meanwhile
            this.followed = this.current({ info, table });
        } catch (e) {
            toast(`Study ${id}: ${errorText(e)}`, 'error');
            return;
        }
        this.main.replaceChildren(this.detail.element);
        this.detail.show(this.followed);
        this.drawList();
        if (FINAL_STATES.has(this.followed.info.state)) return;
        try {
            // (an earlier subscription of the study on this socket would make this one a no-op: see onProgress)
            await this.ctx.ws.request('study.unsubscribe', { study_id: id });
            this.subscribed = id;
            await this.ctx.ws.request('study.subscribe', { study_id: id });
            // rows that finished between the table's read and the subscription
            const table = await this.client.table(id);
            if (epoch === this.epoch && this.followed?.info.id === id) this.update({ ...this.followed, table: mergeRows(this.followed.table, table.columns, table.rows) });
        } catch (e) {
            toast(`Following study ${id}: ${errorText(e)}`, 'error');
        }
    }

    private async unsubscribe(): Promise<void> {
        const id = this.subscribed;
        this.subscribed = null;
        if (id === null) return;
        await this.ctx.ws.request('study.unsubscribe', { study_id: id }).catch(() => undefined);
    }

    private onProgress(event: StudyProgressEvent): void {
        if (!this.followed || event.study_id !== this.followed.info.id) return;
        this.update(applyProgress(this.followed, event));
        if (FINAL_STATES.has(event.state)) {
            // The study's subscription ended with it; a later follow (after Resume) subscribes anew.
            void this.unsubscribe();
            // the final word: the summary (failure reasons, correlations) and every row, from the server
            const id = event.study_id;
            const epoch = this.epoch;
            void Promise.all([this.client.get(id), this.client.table(id)]).then(([info, table]) => {
                if (epoch !== this.epoch || this.followed?.info.id !== id) return;
                if (!FINAL_STATES.has(info.state)) {
                    // An end the study has left behind (a server before d68210d replayed a
                    // resumed study's last event and sent no more): read the study instead.
                    this.finalSeen = false;
                    this.update({ info, table });
                    this.poll(id, epoch);
                    return;
                }
                this.update({ info, table });
                void this.refreshList();
            }, () => undefined);
        }
    }

    /** Reads a study once a second until it ends (when its events do not come). */
    private poll(id: number, epoch: number): void {
        setTimeout(() => {
            if (epoch !== this.epoch || !this.dialog.open) return;
            void Promise.all([this.client.get(id), this.client.table(id)]).then(([info, table]) => {
                if (epoch !== this.epoch || this.followed?.info.id !== id) return;
                this.update({ info, table });
                if (FINAL_STATES.has(info.state)) void this.refreshList();
                else this.poll(id, epoch);
            }, () => this.poll(id, epoch));
        }, POLL_MS);
    }

    /** The study as it now is: within an epoch, a stale non-final state after a final one keeps the final one. */
    private current(study: FollowedStudy): FollowedStudy {
        if (FINAL_STATES.has(study.info.state)) {
            this.finalSeen = true;
            return study;
        }
        const final = this.finalSeen && this.followed?.info.id === study.info.id && FINAL_STATES.has(this.followed.info.state) ? this.followed.info : null;
        return final ? { ...study, info: final } : study;
    }

    private update(study: FollowedStudy): void {
        this.followed = this.current(study);
        this.detail.show(this.followed);
        this.drawList();
    }

    private async applyBest(info: StudyInfo): Promise<void> {
        const best = info.summary.best;
        if (!best) return;
        try {
            await this.ctx.store.execute(new ApplyBestPoint(best.parameters, info.id));
            toast(`Applied the best point of study ${info.id}: Undo (Ctrl+Z) takes it back.`);
        } catch (e) {
            toast(`Apply best point: ${errorText(e)}`, 'error');
        }
    }

    private async act(work: () => Promise<unknown>): Promise<void> {
        try {
            await work();
        } catch (e) {
            toast(errorText(e), 'error');
        }
        await this.refreshList();
        if (this.followed) {
            const id = this.followed.info.id;
            const epoch = this.epoch;
            const info = await this.client.get(id).catch(() => null);
            if (info && epoch === this.epoch && this.followed?.info.id === id) this.update({ ...this.followed, info });
        }
    }
}
