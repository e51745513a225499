// Live mode of the editor: a LiveSession of the open model, its toolbar (LiveBar), its run in
// the plot windows (scrolling), the controls on the drawing (LiveControlLayer, acting only
// while live) and the animated diagram, which gets every frame's values.
import type { EditorStore } from '../editor/EditorStore';
import type { PlotArea } from '../run/PlotArea';
import type { RunData } from '../run/RunData';
import type { Point } from '../model/geometry';
import type { LiveSpeed } from '../protocol/types';
import { toast } from '../ui/dom';
import { LiveSession, type LiveTransport } from './LiveSession';
import { LiveBar } from './LiveBar';
import { LiveControlLayer } from './LiveControlLayer';
import { ChangeLiveControls } from './ChangeLiveControls';
import { askForControl, defaultRange, type ControlChoice } from './ControlDialog';
import { controlsOf, type LiveControl } from './liveControls';
import { defaultControls } from './defaultControls';
import { appendLiveFrame, liveRun } from './liveRun';
import { askForClass, shareableClasses } from './ShareDialog';
import type { LabClass } from '../labs/types';
import './live.css';

/** What the animated diagram offers live mode (src/animation/DiagramAnimation.ts). */
export interface LiveDiagram {
    variables(): string[];
    show(values: ReadonlyMap<string, number>): void;
    clear(): void;
}

export interface LiveModeDeps {
    transport: LiveTransport;
    store: EditorStore;
    canvas: { sceneFromClient(x: number, y: number): Point; addLayer(layer: SVGGElement): void };
    plots: PlotArea;
    modelId(): number;
    /** What to plot when nothing is plotted yet (as ▶ Run does). */
    defaultVariables(): string[];
    /** A live session was kept as a run: the history lists it. */
    recorded(): void;
    /** Whether the model may be changed here (controls added, moved, removed). */
    editable(): boolean;
    reportError(e: unknown): void;
    /** Told before a session starts: the diagram is live mode's from then on (a playback ends). */
    goingLive?(): void;
    /** The user's classes, for "Share with class…"; absent: the user may teach none (no button). */
    classes?(): Promise<LabClass[]>;
}

/** One display frame at 30 frames a second: what ⇥ Step runs. */
const FRAME_SECONDS = 1 / 30;

export class LiveMode {
    readonly session: LiveSession;
    readonly bar: LiveBar;
    readonly layer: LiveControlLayer;
    private run: RunData | null = null;
    private diagram: LiveDiagram | null = null;
    private plotSeconds = 10;
    private readonly detach: (() => void)[] = [];

    constructor(private readonly deps: LiveModeDeps) {
        this.session = new LiveSession(deps.transport);
        this.layer = new LiveControlLayer(deps.store, deps.canvas, {
            set: (name, value) => void this.session.set(name, value),
            edit: (index) => void this.editControl(index),
            editable: deps.editable,
            error: deps.reportError,
        });
        deps.canvas.addLayer(this.layer.element);
        this.bar = new LiveBar(this.session, {
            goLive: (speed) => void this.goLive(speed),
            stop: () => void this.session.stop(),
            record: () => void this.record(),
            step: (single) => void this.step(single),
            plotWindowChanged: (seconds) => { this.plotSeconds = seconds; },
            share: deps.classes ? () => void this.share() : undefined,
        });
        this.plotSeconds = this.bar.plotWindow();
        this.detach.push(
            this.session.onFrame((values, frame) => {
                if (this.run && this.session.started) appendLiveFrame(this.run, frame, this.plotSeconds, this.session.started.start);
                deps.plots.liveUpdated();
                this.diagram?.show(values);
                this.bar.refresh();
            }),
            this.session.subscribe(() => { if (this.session.status.phase === 'stopped') this.leave(); }),
        );
    }

    /** The animated diagram to draw each frame (and to clear when live mode ends). */
    attachDiagram(diagram: LiveDiagram): void { this.diagram = diagram; }

    dispose(): void {
        if (this.session.active) void this.session.stop();
        this.leave();
        for (const d of this.detach) d();
        this.session.dispose();
        this.layer.dispose();
    }

    async goLive(speed: LiveSpeed): Promise<void> {
        const { plots, store } = this.deps;
        this.deps.goingLive?.();
        if (plots.allVariables().length === 0) for (const v of this.deps.defaultVariables()) plots.addVariable(v);
        const variables = [...new Set([...plots.allVariables(), ...(this.diagram?.variables() ?? [])])];
        if (store.dirty) toast('Live mode runs the saved model: changes not saved yet are not in it.');
        if (!await this.session.start(this.deps.modelId(), variables, speed)) return;
        const started = this.session.started!;
        this.run = liveRun(started.session_id, started.variables);
        plots.showLive(this.run);
        const liveNames = new Set(started.live_values.map((v) => v.name));
        this.layer.setLive({
            liveNames,
            defaults: defaultControls(store.system, store.path, liveNames, controlsOf(store.model)),
            values: this.session.setValues,
            // on an assignment's locked copy: only the listed values are live, within its bounds
            bounds: new Map(started.live_values.map((v) => [v.name, { min: v.min, max: v.max }])),
        });
    }

    /** Back to editing: the controls are inert, the plots show the model's runs, the diagram the editor's drawing. */
    private leave(): void {
        this.layer.setLive(null);
        this.diagram?.clear();
        if (this.run) {
            this.run = null;
            this.deps.plots.showLive(null);
        }
    }

    private async step(single: boolean): Promise<void> {
        const timestep = this.session.started?.step ?? 0;
        const steps = single || timestep <= 0 ? 1 : Math.max(1, Math.round(FRAME_SECONDS / timestep));
        await this.session.step(steps);
    }

    /** "Share with class…": a class the user teaches may watch the session (docs/live-sessions.md). */
    private async share(): Promise<void> {
        let classes: LabClass[];
        try {
            classes = shareableClasses(await this.deps.classes!());
        } catch (e) {
            this.deps.reportError(e);
            return;
        }
        if (classes.length === 0) {
            toast('You teach no class (that is not archived) to share the session with.');
            return;
        }
        const classId = await askForClass(classes);
        if (classId === null || !await this.session.share(classId)) return;
        toast(`Shared with ${classes.find((c) => c.id === classId)?.name ?? 'the class'}: its members can watch from the class page.`);
    }

    private async record(): Promise<void> {
        const kept = await this.session.record();
        if (!kept) return;
        toast(`Kept as a run in the history (${kept.samples} samples${kept.full ? ', the recording was full' : ''}).`);
        this.deps.recorded();
    }

    /** What a control may be bound to: the running session's live values, else the component's number parameters. */
    private choices(component?: string): ControlChoice[] {
        const live = this.session.liveValues;
        const prefix = this.deps.store.path.map((p) => `${p}$`).join('');
        if (live.length > 0) {
            const own = component ? live.filter((v) => v.name.startsWith(`${prefix}${component}.`)) : [];
            return (own.length > 0 ? own : live).map((v) => ({ name: v.name, value: this.session.setValues.get(v.name) ?? v.value }));
        }
        const comps = this.deps.store.system.components.filter((c) => !component || c.name === component);
        return comps.flatMap((c) => c.parameters.filter((p) => p.type === 'double' && Number.isFinite(Number(p.value)))
            // an input's start value (Step.y_A#Value) is set live by the input's name (Step.y_A)
            .map((p) => ({ name: `${prefix}${c.name}.${p.name.replace(/#Value$/, '')}`, value: Number(p.value) })));
    }

    /** "Add live control" on a component: a slider under it, bound to the value the user picks. */
    async addControlFor(component: string): Promise<void> {
        const { store } = this.deps;
        const comp = store.system.components.find((c) => c.name === component);
        if (!comp) return;
        const choices = this.choices(component);
        const first = choices[0] ?? { name: '', value: 0 };
        const draft: LiveControl = { kind: 'slider', name: first.name, ...defaultRange(first.value), x: comp.pose.x, y: comp.pose.y + 48, path: [...store.path] };
        const control = await askForControl(choices, draft);
        if (!control) return;
        await store.execute(new ChangeLiveControls([...controlsOf(store.model), control], 'Add live control')).catch(this.deps.reportError);
    }

    private async editControl(index: number): Promise<void> {
        const { store } = this.deps;
        const saved = controlsOf(store.model);
        const control = saved[index];
        if (!control) return;
        const changed = await askForControl(this.choices(), control);
        if (!changed) return;
        const next = saved.map((c, i) => (i === index ? changed : c));
        await store.execute(new ChangeLiveControls(next, 'Change live control')).catch(this.deps.reportError);
    }
}
