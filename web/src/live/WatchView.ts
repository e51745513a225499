// Watching a live session read-only (docs/live-sessions.md, "In a lab"): a class member opens
// the session its teacher shares. The model the session runs comes from the session
// (live.model: the student may not read the teacher's model), drawn as the editor draws it;
// the animated diagram and the plots follow every frame; nothing here controls the session.
import type { Session } from '../app/Session';
import { appSocket } from '../app/appSocket';
import { EditorStore } from '../editor/EditorStore';
import { CanvasView } from '../editor/CanvasView';
import { DiagramAnimation } from '../animation/DiagramAnimation';
import { RunController } from '../run/RunController';
import { PlotArea } from '../run/PlotArea';
import { sinkVariables } from '../model/variables';
import { errorText, h } from '../ui/dom';
import type { LiveModelData } from '../protocol/types';
import { LiveSession } from './LiveSession';
import { appendLiveFrame, liveRun } from './liveRun';
import { watchStatusText, watchedPlotVariables } from './watchText';
import './live.css';

export interface WatchPage { dispose(): void }

/** Seconds of model time the plots show, scrolling on as the session runs. */
const PLOT_SECONDS = 10;

export async function renderWatch(root: HTMLElement, session: Session, sessionId: number,
    back: { href: string; label: string }): Promise<WatchPage> {
    root.replaceChildren(h('main', { class: 'loading' }, h('p', { class: 'muted' }, 'Opening the live session…')));
    const ws = appSocket(session);
    let drawing: LiveModelData;
    try {
        await ws.connect();
        drawing = await ws.request('live.model', { session_id: sessionId });
    } catch (e) {
        ws.close();
        root.replaceChildren(h('main', { class: 'error-page' }, h('h1', {}, 'Cannot watch the live session'),
            h('p', { class: 'form-error', role: 'alert', 'data-testid': 'watch-error' },
                (e as { code?: string }).code === 'not_found' ? 'The live session has ended, or is not shared with you.' : errorText(e)),
            h('a', { href: back.href }, back.label)));
        return { dispose: () => undefined };
    }

    // Read-only: the store never sends an edit, the canvas allows no drag that would make one.
    const store = new EditorStore(drawing.model, () => Promise.reject(new Error('a watched live session is read-only')));
    const canvas = new CanvasView(store, { onPortClick: () => undefined, onComponentDoubleClick: () => undefined, allows: () => false });
    const animation = new DiagramAnimation(canvas, store);
    const runs = new RunController({ request: ws.request.bind(ws), onEvent: ws.onEvent.bind(ws),
        resultsJson: session.rest.resultsJson.bind(session.rest), onResubscribe: ws.onResubscribe.bind(ws) });
    const plots = new PlotArea(runs, session.units);
    void session.units.load();
    const run = liveRun(sessionId, drawing.variables);
    plots.showLive(run);
    for (const name of watchedPlotVariables(sinkVariables(drawing.model), drawing.variables)) plots.addVariable(name);
    const start = drawing.model.system.simulation?.start ?? 0;

    const live = new LiveSession({ request: ws.request.bind(ws), onLive: ws.onLive.bind(ws), onStatus: ws.onStatus.bind(ws) });
    const status = h('span', { class: 'live-status', 'data-testid': 'watch-status', role: 'status' });
    const message = h('span', { class: 'live-message', 'data-testid': 'watch-message', role: 'alert' });
    const showStatus = () => {
        status.textContent = watchStatusText(live.status);
        message.textContent = live.status.message;
    };
    live.subscribe(showStatus);
    live.onFrame((values, frame) => {
        appendLiveFrame(run, frame, PLOT_SECONDS, start);
        plots.liveUpdated();
        animation.show(values);
        showStatus();
    });

    const header = h('header', { class: 'editor-header' },
        h('a', { href: back.href, class: 'back' }, `← ${back.label}`),
        h('h1', { 'data-testid': 'watch-model-name' }, drawing.model_name),
        h('span', { class: 'badge' }, 'watching live: read-only'),
        h('div', { class: 'live-bar watch-bar' }, status, message));
    root.replaceChildren(h('main', { class: 'editor watch-page', 'data-testid': 'watch-page' },
        header,
        h('div', { class: 'editor-body watch-body' }, h('section', { class: 'canvas-column' }, canvas.element)),
        h('section', { class: 'run-area' }, h('div', { class: 'run-body' }, plots.element))));
    canvas.render();
    showStatus();
    void live.watch(sessionId);
    return {
        dispose: () => {
            live.dispose();
            animation.clear();
            plots.dispose();
            ws.close();
        },
    };
}
