// Playback of a recorded run on the animated diagram: a timeline under the drawing with play,
// pause, speed and a slider to scrub. At each instant the diagram shows the run's values there
// (between samples, interpolated) and every plot window marks the time with a cursor line.
import type { DiagramAnimation } from './DiagramAnimation';
import type { RunData } from '../run/RunData';
import { advance, changeMarks, stepOfTime, timeOfStep, valuesAt, type RecordedChange } from './timeline';
import { runPressureRange } from './pressureScale';
import { h } from '../ui/dom';

/** Slider steps over the run: fine enough to reach any sample a plot shows apart. */
const STEPS = 2000;
const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 5, 10];

export interface PlaybackHost {
    animation: DiagramAnimation;
    /** Marks the time in the plot windows (null: no cursor). */
    setPlotTime(time: number | null): void;
    /** Loads the run's stored values of those of `names` it logged. */
    load(run: RunData, names: string[]): Promise<void>;
    /** The changes made while the run was recorded, if it is a recorded live session. */
    changes(run: RunData): Promise<RecordedChange[]>;
    /** Playback ended (closed, or another run replaced it). */
    closed?(): void;
}

export class PlaybackBar {
    readonly element: HTMLElement;
    private readonly playButton: HTMLButtonElement;
    private readonly slider: HTMLInputElement;
    private readonly timeText: HTMLElement;
    private readonly speed: HTMLSelectElement;
    private readonly title: HTMLElement;
    /** Over the slider: a mark per change of a recorded live session; a click goes there. */
    private readonly marks: HTMLElement;
    private run: RunData | null = null;
    private columns = new Map<string, number[]>();
    private readonly values = new Map<string, number>();
    private t = 0;
    private frame = 0;
    private lastWall = 0;

    constructor(private readonly host: PlaybackHost) {
        this.playButton = h('button', { class: 'playback-play', 'data-testid': 'playback-play', 'aria-label': 'Play', title: 'Play (Space)', onclick: () => this.toggle() }, '▶');
        this.slider = h('input', {
            type: 'range', min: 0, max: STEPS, step: 1, value: 0, class: 'playback-slider', 'data-testid': 'playback-slider', 'aria-label': 'Time',
            oninput: () => { this.pause(); this.seek(timeOfStep(this.start, this.end, STEPS, Number(this.slider.value))); },
        });
        this.timeText = h('span', { class: 'playback-time', 'data-testid': 'playback-time' });
        this.speed = h('select', { class: 'playback-speed', 'data-testid': 'playback-speed', 'aria-label': 'Speed', title: 'Simulated seconds per second' },
            ...SPEEDS.map((v) => h('option', { value: v, selected: v === 1 }, `${v}×`)));
        this.title = h('span', { class: 'playback-title' });
        this.marks = h('div', { class: 'playback-changes', 'data-testid': 'playback-changes' });
        this.element = h('div', {
            class: 'playback-bar', 'data-testid': 'playback-bar', hidden: true, role: 'group', 'aria-label': 'Playback',
            onkeydown: (e: KeyboardEvent) => {
                if (e.key === ' ' && !(e.target instanceof HTMLSelectElement)) { e.preventDefault(); this.toggle(); }
            },
        },
        this.title, this.playButton, h('div', { class: 'playback-track' }, this.slider, this.marks), this.timeText, this.speed,
        h('button', { class: 'playback-close', 'data-testid': 'playback-close', 'aria-label': 'Close playback', title: 'Leave playback', onclick: () => this.close() }, '✕'));
    }

    get playing(): boolean { return this.frame !== 0; }
    get time(): number { return this.t; }
    get shownRun(): RunData | null { return this.run; }
    private get start(): number { return this.run?.time[0] ?? 0; }
    private get end(): number { return this.run?.time.at(-1) ?? 0; }

    /** Plays back `run` (a finished run with stored results) from its start, paused. */
    async open(run: RunData): Promise<void> {
        this.pause();
        this.run = run;
        this.title.textContent = run.label;
        this.element.hidden = false;
        this.marks.replaceChildren();
        const [loaded, changes] = await Promise.all([this.loadValues(run), this.host.changes(run)]);
        if (!loaded) return;
        this.showChanges(changes);
        // the colours span the run's pressures (the user may change the range on the scale)
        const [low, high] = runPressureRange([...this.columns].filter(([n]) => n.endsWith('#Pressure')).map(([, c]) => c));
        this.host.animation.range.set(low, high);
        this.seek(this.start);
    }

    /** The drawing shows another system (a subsystem entered or left): its values are loaded, at the same instant. */
    async refresh(): Promise<void> {
        const run = this.run;
        if (!run) return;
        // drawn over the new system at once, its parts at rest until their values are in
        this.seek(this.t);
        if (await this.loadValues(run)) this.seek(this.t);
    }

    /** Loads the values the drawing needs; false when another run was opened meanwhile. */
    private async loadValues(run: RunData): Promise<boolean> {
        const names = this.host.animation.variables();
        await this.host.load(run, names);
        if (this.run !== run) return false;
        this.columns = new Map(names.flatMap((n) => {
            const c = run.columns.get(n);
            return c ? [[n, c] as [string, number[]]] : [];
        }));
        return true;
    }

    private showChanges(changes: RecordedChange[]): void {
        this.marks.replaceChildren(...changeMarks(changes, this.start, this.end).map((m) => {
            const mark = h('button', {
                class: 'playback-change', 'data-testid': 'playback-change', title: m.label, 'aria-label': m.label,
                onclick: () => { this.pause(); this.seek(m.time); },
            });
            // set through the CSSOM: the page's policy refuses style attributes
            mark.style.left = `${(m.at * 100).toFixed(3)}%`;
            return mark;
        }));
    }

    /** Leaves playback: the drawing and the plots as they were. */
    close(): void {
        this.pause();
        if (!this.run) return;
        this.run = null;
        this.element.hidden = true;
        this.host.animation.clear();
        this.host.setPlotTime(null);
        this.host.closed?.();
    }

    /** Shows the run at time `t` (clamped to the run). */
    seek(t: number): void {
        if (!this.run) return;
        this.t = Math.max(this.start, Math.min(this.end, t));
        this.host.animation.show(valuesAt(this.run.time, this.columns, this.t, this.values));
        this.host.setPlotTime(this.t);
        this.slider.value = String(stepOfTime(this.start, this.end, STEPS, this.t));
        this.timeText.textContent = `${this.t.toFixed(3)} s / ${this.end.toFixed(3)} s`;
    }

    play(): void {
        if (!this.run || this.playing) return;
        // from the end, playing starts over
        if (this.t >= this.end) this.seek(this.start);
        this.lastWall = performance.now();
        this.playButton.textContent = '⏸';
        this.playButton.setAttribute('aria-label', 'Pause');
        const tick = (now: number) => {
            const step = advance(this.t, (now - this.lastWall) / 1000, Number(this.speed.value), this.end);
            this.lastWall = now;
            this.seek(step.t);
            if (step.ended) this.pause();
            else this.frame = requestAnimationFrame(tick);
        };
        this.frame = requestAnimationFrame(tick);
    }

    pause(): void {
        if (this.frame) cancelAnimationFrame(this.frame);
        this.frame = 0;
        this.playButton.textContent = '▶';
        this.playButton.setAttribute('aria-label', 'Play');
    }

    private toggle(): void {
        if (this.playing) this.pause(); else this.play();
    }
}
