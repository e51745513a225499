// The live controls of the run toolbar, beside ▶ Run: go live; then pause/resume, step,
// speed (0.01× to 100×, or as fast as the server can), the plots' scrolling window, keep
// as a run, stop; the model time, the speed the server achieves when it cannot keep up, and
// in words why the session stopped or what it refused.
import { h } from '../ui/dom';
import type { LiveSpeed } from '../protocol/types';
import type { LiveSession } from './LiveSession';
import { formatTime } from './liveErrors';
import { PLOT_WINDOWS } from './liveRun';

export const SPEEDS: readonly LiveSpeed[] = [0.01, 0.1, 0.25, 0.5, 1, 2, 5, 10, 100, 'max'];

export interface LiveBarActions {
    goLive(speed: LiveSpeed): void;
    stop(): void;
    record(): void;
    /** Steps a paused session: one display frame of model time, or one time step with Shift. */
    step(single: boolean): void;
    plotWindowChanged(seconds: number): void;
    /** Shares the session with a class the user teaches; absent: the user teaches none. */
    share?(): void;
}

export class LiveBar {
    readonly element: HTMLElement;
    private readonly goButton: HTMLButtonElement;
    private readonly pauseButton: HTMLButtonElement;
    private readonly stepButton: HTMLButtonElement;
    private readonly stopButton: HTMLButtonElement;
    private readonly recordButton: HTMLButtonElement;
    private readonly shareButton: HTMLButtonElement | null;
    private readonly speed: HTMLSelectElement;
    private readonly window: HTMLSelectElement;
    private readonly status: HTMLElement;
    private readonly message: HTMLElement;

    constructor(private readonly session: LiveSession, actions: LiveBarActions) {
        this.goButton = h('button', {
            class: 'live-go', 'data-testid': 'live', title: 'Run the saved model in time with the clock and change its inputs while it runs',
            onclick: () => actions.goLive(this.chosenSpeed()),
        }, '◉ Live');
        this.pauseButton = h('button', { 'data-testid': 'live-pause', onclick: () => void this.togglePause() }, '‖ Pause');
        this.stepButton = h('button', {
            'data-testid': 'live-step', title: 'Run one display frame of model time (Shift: one time step)',
            onclick: (e: MouseEvent) => actions.step(e.shiftKey),
        }, '⇥ Step');
        this.speed = h('select', { 'data-testid': 'live-speed', 'aria-label': 'Live speed', title: 'Model seconds per second of the clock' },
            ...SPEEDS.map((s) => h('option', { value: String(s) }, s === 'max' ? 'max' : `${s}×`)));
        this.speed.value = '1';
        this.speed.addEventListener('change', () => void session.setSpeed(this.chosenSpeed()));
        this.window = h('select', { 'data-testid': 'live-window', 'aria-label': 'Plotted time window', title: 'How many seconds of model time the plots show' },
            ...PLOT_WINDOWS.map((s) => h('option', { value: String(s) }, `last ${s} s`)));
        this.window.value = '10';
        this.window.addEventListener('change', () => actions.plotWindowChanged(Number(this.window.value)));
        this.recordButton = h('button', {
            'data-testid': 'live-record', title: 'Keep what the session has run so far as a run in the history (it goes on)', onclick: () => actions.record(),
        }, '● Keep as run');
        this.stopButton = h('button', { 'data-testid': 'live-stop', onclick: () => actions.stop() }, '■ Stop');
        const share = actions.share;
        this.shareButton = share ? h('button', {
            'data-testid': 'live-share', title: 'Let a class you teach watch this session read-only', onclick: () => share(),
        }, 'Share with class…') : null;
        this.status = h('span', { class: 'live-status', 'data-testid': 'live-status', role: 'status' });
        this.message = h('span', { class: 'live-message', 'data-testid': 'live-message', role: 'alert' });
        this.element = h('div', { class: 'live-bar' }, this.goButton, this.pauseButton, this.stepButton, this.speed, this.window,
            this.recordButton, this.stopButton, this.shareButton, this.status, this.message);
        session.subscribe(() => this.refresh());
        this.refresh();
    }

    plotWindow(): number { return Number(this.window.value); }

    private chosenSpeed(): LiveSpeed {
        return this.speed.value === 'max' ? 'max' : Number(this.speed.value);
    }

    private async togglePause(): Promise<void> {
        if (this.session.status.phase === 'paused') await this.session.resume();
        else await this.session.pause();
    }

    /** Also called per frame by the live mode: the model time moves on. */
    refresh(): void {
        const { phase, speed, achievedSpeed, behind, modelTime, message, notice } = this.session.status;
        const active = phase === 'starting' || phase === 'running' || phase === 'paused';
        this.element.dataset.phase = phase;
        this.goButton.hidden = active;
        for (const el of [this.pauseButton, this.stepButton, this.recordButton, this.stopButton, this.window, this.shareButton]) {
            if (el) el.hidden = !active;
        }
        this.pauseButton.disabled = phase === 'starting';
        this.pauseButton.textContent = phase === 'paused' ? '▶ Resume' : '‖ Pause';
        this.stepButton.disabled = phase !== 'paused';
        this.recordButton.disabled = phase === 'starting';
        if (document.activeElement !== this.speed) this.speed.value = String(speed);
        const pace = speed === 'max' ? 'as fast as it can' : `${speed}×`;
        const achieved = behind ? ` · achieved ${formatTime(achievedSpeed)}× (the server cannot keep up)` : '';
        this.status.dataset.behind = String(behind);
        this.status.textContent = phase === 'starting' ? 'Going live…'
            : active ? `${phase === 'paused' ? 'Paused' : 'Live'} · t = ${modelTime.toFixed(2)} s · ${pace}${achieved}` : '';
        const text = message || notice;
        this.message.textContent = text;
        this.message.hidden = text === '';
    }
}
