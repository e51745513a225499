// The plot windows under the editor. Clicked variables go to the active window; one of a unit
// the window has no axis for, beyond four, waits for the user to say where it goes. A run chosen
// in the run history is shown in every window; an FFT, Bode or XY window analyses the run its
// plot window shows.
import { PlotWindow } from './PlotWindow';
import { AxisChoice, type PendingVariable } from './axisChoice';
import { unitOfVariable } from './units';
import { AnalysisWindow, type AnalysisKind } from './AnalysisWindow';
import { XyWindow } from './XyWindow';
import type { RunController } from './RunController';
import type { RunData } from './RunData';
import type { SavedPlots } from './runHistory';
import type { UnitPreferences } from './unitPreferences';
import { h, toast, errorText } from '../ui/dom';

export class PlotArea {
    readonly element: HTMLElement;
    readonly windows: PlotWindow[] = [];
    readonly analyses: (AnalysisWindow | XyWindow)[] = [];
    /** The plot window each analysis was opened from: it analyses the run that window shows. */
    private readonly analysed = new Map<AnalysisWindow | XyWindow, PlotWindow>();
    private active: PlotWindow | null = null;
    private nextId = 1;
    private readonly list: HTMLElement;
    private scheduled = false;
    /** A zoom or pan waiting to be remembered: at most one save per pause of the mouse, not one per frame. */
    private zoomSave: ReturnType<typeof setTimeout> | undefined;
    private fetchedFor = 0;
    private playbackTime: number | null = null;
    private readonly unsubscribe: () => void;
    private readonly unsubscribeChoice: () => void;
    private readonly choice: AxisChoice<PlotWindow>;
    /** A live session's run (src/live/): shown after the model's runs while it streams. */
    private live: RunData | null = null;

    /**
     * `units` are the user's display units, shared by all windows; `onLayoutChange` is told when the
     * user adds or removes a variable, closes a window or has zoomed one (to remember them).
     */
    constructor(private readonly runs: RunController, private readonly units: UnitPreferences,
        private readonly onLayoutChange: () => void = () => undefined,
        /** The model's signal sources: a Bode window's default input. */
        private readonly sources: () => string[] = () => []) {
        this.list = h('div', { class: 'plot-list' });
        window.addEventListener('pagehide', this.saveZoom);
        this.choice = new AxisChoice<PlotWindow>({
            addAxis: (w, variables) => this.addTo(w, variables),
            newWindow: (variables) => {
                const w = this.addWindow();
                this.addTo(w, variables);
                // where the user sees it, not below the fold of the run area
                w.element.scrollIntoView({ block: 'nearest' });
            },
        });
        this.element = h('div', { class: 'plot-area' },
            h('div', { class: 'plot-toolbar' }, h('button', { class: 'small', onclick: () => this.addWindow(), 'data-testid': 'new-plot' }, '+ New plot window'), this.choice.element),
            this.list);
        this.unsubscribe = runs.subscribe(() => {
            // variables added during a run were not streamed: load them when it ends
            const run = runs.current;
            if (run?.finished && run.jobId !== this.fetchedFor) {
                this.fetchedFor = run.jobId;
                runs.ensure(this.allVariables()).catch((e) => toast(`Results: ${errorText(e)}`, 'error'));
            }
            this.scheduleUpdate();
        });
        this.unsubscribeChoice = runs.onChoose((run) => {
            for (const w of this.windows) {
                w.show(run.jobId);
                this.refresh(w);
            }
        });
    }

    /** Closes every window (the editor was left): their resize observers stop, and runs are no longer followed. */
    dispose(): void {
        this.saveZoom();
        window.removeEventListener('pagehide', this.saveZoom);
        this.unsubscribe();
        this.unsubscribeChoice();
        for (const w of [...this.windows]) this.close(w);
        for (const a of [...this.analyses]) this.closeAnalysis(a);
    }

    addWindow(): PlotWindow {
        const w = new PlotWindow(this.nextId++, this.units, {
            close: (x) => { this.close(x); this.onLayoutChange(); },
            activate: (x) => this.activate(x),
            changed: (x) => { this.refresh(x); this.onLayoutChange(); },
            zoomed: () => this.saveZoomSoon(),
            analyse: (x, kind) => (kind === 'xy' ? this.openXy(x) : this.openAnalysis(kind, x)),
        });
        this.windows.push(w);
        w.setPlaybackTime(this.playbackTime);
        this.list.append(w.element);
        this.activate(w);
        return w;
    }

    /** A spectrum or Bode window of variables of a plot window (the first one or two chosen). */
    openAnalysis(kind: AnalysisKind, plot: PlotWindow): AnalysisWindow {
        const w = new AnalysisWindow(this.nextId++, kind, plot.variables, (v) => plot.labelOf(v), (x) => this.closeAnalysis(x),
            { sources: this.sources(), load: (names) => this.runs.ensure(names, [plot.shownRun()]) });
        return this.addAnalysis(w, plot);
    }

    /** An XY plot of two variables of a plot window. */
    openXy(plot: PlotWindow): XyWindow {
        return this.addAnalysis(new XyWindow(this.nextId++, plot.variables, (v) => plot.labelOf(v), (x) => this.closeAnalysis(x)), plot);
    }

    private addAnalysis<W extends AnalysisWindow | XyWindow>(w: W, plot: PlotWindow): W {
        this.analyses.push(w);
        this.analysed.set(w, plot);
        this.list.append(w.element);
        w.update(plot.shownRun());
        return w;
    }

    private closeAnalysis(w: AnalysisWindow | XyWindow): void {
        this.analyses.splice(this.analyses.indexOf(w), 1);
        this.analysed.delete(w);
        w.destroy();
    }

    /** Analyses follow the run their plot window shows (one whose window was closed keeps the run it had). */
    private updateAnalyses(): void {
        for (const a of this.analyses) a.update(this.analysed.get(a)!.shownRun());
    }

    private activate(w: PlotWindow): void {
        this.active = w;
        for (const x of this.windows) x.setActive(x === w);
    }

    private close(w: PlotWindow): void {
        const i = this.windows.indexOf(w);
        if (i >= 0) this.windows.splice(i, 1);
        if (this.choice.asking === w) this.choice.dismiss();
        w.destroy();
        if (this.active === w) this.active = this.windows.at(-1) ?? null;
        if (this.active) this.activate(this.active);
    }

    /**
     * Adds a variable to the active plot window (a new one if there is none); if its unit would
     * be one axis too many there, the user is asked whether to add the axis or open a window.
     */
    addVariable(name: string, label?: string, unit = unitOfVariable(name)): void {
        const w = this.active ?? this.addWindow();
        if (!w.hasRoomFor(unit)) {
            this.choice.ask(w, { name, label, unit });
            return;
        }
        this.addTo(w, [{ name, label, unit }]);
    }

    private addTo(w: PlotWindow, variables: PendingVariable[]): void {
        for (const v of variables) w.add(v.name, v.label, v.unit);
        this.activate(w);
        this.refresh(w);
        this.onLayoutChange();
    }

    /** The plot windows' variables as they are shown, and their zooms, to open them again later. */
    layout(): SavedPlots {
        return this.windows.map((w) => {
            const variables = w.variables.map((name) => ({ name, label: w.labelOf(name), unit: w.unitOf(name) }));
            const zoom = w.zoom();
            return zoom ? { variables, zoom } : { variables };
        });
    }

    /** Opens a window per saved one, with its variables and zoom. */
    openLayout(saved: SavedPlots): void {
        for (const { variables, zoom } of saved) {
            const w = this.addWindow();
            for (const v of variables) w.add(v.name, v.label, v.unit);
            if (zoom) w.restoreZoom(zoom);
            this.refresh(w);
        }
    }

    private saveZoomSoon(): void {
        clearTimeout(this.zoomSave);
        this.zoomSave = setTimeout(this.saveZoom, 400);
    }

    // also when the page goes (a reload right after a zoom)
    private readonly saveZoom = (): void => {
        if (this.zoomSave === undefined) return;
        clearTimeout(this.zoomSave);
        this.zoomSave = undefined;
        this.onLayoutChange();
    };

    /** Marks `time` in every plot window with the playback cursor (null: none). */
    setPlaybackTime(time: number | null): void {
        this.playbackTime = time;
        for (const w of this.windows) w.setPlaybackTime(time);
    }

    /** Every plotted variable, in window order, without repeats. */
    allVariables(): string[] {
        return [...new Set(this.windows.flatMap((w) => w.variables))];
    }

    /** Shows a live session's run in every window as the newest run (null: the model's runs again). */
    showLive(run: RunData | null): void {
        this.live = run;
        for (const w of this.windows) this.refresh(w);
    }

    /** The live run got a frame: redrawn with the next animation frame. */
    liveUpdated(): void { this.scheduleUpdate(); }

    private generations(): readonly RunData[] {
        return this.live ? [...this.runs.generations, this.live] : this.runs.generations;
    }

    private refresh(w: PlotWindow): void {
        w.update(this.generations());
        this.updateAnalyses();
        // (a run still going has no stored results: ensure() passes it over)
        this.runs.ensure(w.variables, w.shownRuns()).catch((e) => toast(`Results: ${errorText(e)}`, 'error'));
    }

    // at most one redraw per animation frame while frames stream in; a hidden page gets no
    // animation frames, yet a plot detached into a window of its own must go on streaming
    private scheduleUpdate(): void {
        if (this.scheduled) return;
        this.scheduled = true;
        const redraw = () => {
            this.scheduled = false;
            for (const w of this.windows) w.update(this.generations());
            this.updateAnalyses();
        };
        if (document.hidden) setTimeout(redraw, 50);
        else requestAnimationFrame(redraw);
    }
}
