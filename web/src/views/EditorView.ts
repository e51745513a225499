// The model editor page: palette, canvas, parameter panel, run controls and plots, wired to
// one WebSocket on which the model is open.
import { appSocket } from '../app/appSocket';
import { ApiError } from '../api/ApiError';
import { EditorStore } from '../editor/EditorStore';
import { CanvasView } from '../editor/CanvasView';
import { ParameterPanel } from '../editor/ParameterPanel';
import { createPalette } from '../editor/Palette';
import { SetSimulationSettings } from '../editor/commands';
import { EditorActions } from '../editor/EditorActions';
import { ContextMenu } from '../editor/ContextMenu';
import { menuFor, type MenuContext } from '../editor/editorMenus';
import { MessageArea } from '../editor/MessageArea';
import { ShortcutHelp } from '../editor/ShortcutHelp';
import { shortcutFor, type ShortcutId } from '../editor/shortcuts';
import { RunController } from '../run/RunController';
import { PlotArea } from '../run/PlotArea';
import { signalSources } from '../analysis/bodeDefaults';
import { RunPanel } from '../run/RunPanel';
import { HistoryPanel } from '../run/HistoryPanel';
import { parameterTexts } from '../run/runDifferences';
import { HISTORY_PAGE, isLoggedVariable, loadPlots, savePlots } from '../run/runHistory';
import { portVariables, sinkVariables } from '../model/variables';
import { primaryVariables } from '../model/nodeTypes';
import { downloadText, errorText, h, toast } from '../ui/dom';
import { createSplitter } from '../ui/splitter';
import { openFmuDialog } from '../fmu/FmuDialog';
import { StudyPanel } from '../studies/StudyPanel';
import { LiveMode } from '../live/LiveMode';
import { DiagramAnimation } from '../animation/DiagramAnimation';
import { PlaybackBar } from '../animation/PlaybackBar';
import { EditPermissions, permittedTransport } from '../editor/EditPermissions';
import { instructionsPanel } from '../labs/InstructionsPanel';
import type { Session } from '../app/Session';
import { modelRouteHash, parseModelRoute } from '../app/modelRoute';
import { systemAt } from '../model/modelState';
import type { CatalogueEntry, JobInfo, ModelOpenedData, ModelSummary, PortRef } from '../protocol/types';

export interface EditorPage {
    dispose(): void;
    dirty(): boolean;
    /** Shows the subsystem at `path` (the address changed: Back, Forward); the top level if it is gone. */
    showPath(path: string[]): void;
}

/** Where the header's back link leads (default: the model list); `note` says what the model is for. */
export interface BackLink { href: string; label: string; note?: string }

export async function renderEditor(root: HTMLElement, session: Session, modelId: number,
    navigate: (hash: string, replace?: boolean) => void, back: BackLink = { href: '#/models', label: 'Models' },
    initialPath: string[] = []): Promise<EditorPage> {
    root.replaceChildren(h('main', { class: 'loading' }, h('p', { class: 'muted' }, 'Opening model…')));
    const rest = session.rest;
    // the summary, the catalogue and the model are asked for at once: one after the other
    // they took most of the time to open a big model
    const ws = appSocket(session);
    const opening = Promise.all([
        rest.components(),
        ws.connect().then(() => ws.request('model.open', { model_id: modelId })),
    ]);
    opening.catch(() => undefined);   // a failure is shown below, once the summary is in
    // an assignment's copy (#/model/<id>?assignment=<aid>) brings what may change and the instructions
    const assignmentId = /[?&]assignment=(\d+)/.exec(location.hash)?.[1];
    const assignmentLoading = assignmentId ? session.labs.getAssignment(Number(assignmentId)).catch(() => null) : Promise.resolve(null);
    let summary: ModelSummary;
    try {
        summary = await rest.getModel(modelId);
    } catch (e) {
        ws.close();
        const message = e instanceof ApiError && e.code === 'not_found' ? 'Model not found (it does not exist or is not yours).' : errorText(e);
        root.replaceChildren(h('main', { class: 'error-page' }, h('h1', {}, 'Cannot open the model'),
            h('p', { class: 'form-error', role: 'alert', 'data-testid': 'open-error' }, message), h('a', { href: '#/models' }, 'Back to the models')));
        return { dispose: () => undefined, dirty: () => false, showPath: () => undefined };
    }
    let catalogue: CatalogueEntry[];
    let opened: ModelOpenedData;
    try {
        [catalogue, opened] = await opening;
    } catch (e) {
        ws.close();
        root.replaceChildren(h('main', { class: 'error-page' }, h('h1', {}, 'Cannot open the model'),
            h('p', { class: 'form-error', role: 'alert', 'data-testid': 'open-error' }, errorText(e)), h('a', { href: '#/models' }, 'Back to the models')));
        return { dispose: () => undefined, dirty: () => false, showPath: () => undefined };
    }

    const assignment = await assignmentLoading;
    const permissions = EditPermissions.forAssignment(assignment, summary.owner.id === session.user?.id);
    // An edit request carries its fields beside its type; the client sets the type itself. What
    // a locked copy may not change is refused before it is sent.
    const store = new EditorStore(opened.model, permittedTransport(permissions, (request) => ws.request(request.type, request)));
    // The subsystem on screen is in the address (modelRoute.ts): entering one is a step that
    // Back returns from, and the address, when Back or Forward changes it, says what to show.
    let pathInAddress = JSON.stringify(initialPath);
    const addressOf = (path: string[]) => {
        const route = parseModelRoute(location.hash);
        return route && modelRouteHash({ ...route, path });
    };
    const showPath = (path: string[]): void => {
        const shown = systemAt(store.model, path) ? path : [];
        pathInAddress = JSON.stringify(shown);
        if (JSON.stringify(store.path) !== pathInAddress) store.enterSystem(shown);
        const corrected = shown === path ? null : addressOf(shown);   // a subsystem that is gone
        if (corrected) navigate(corrected, true);
    };
    showPath(initialPath);
    store.subscribe(() => {
        const path = JSON.stringify(store.path);
        if (path === pathInAddress) return;
        pathInAddress = path;
        const address = addressOf(store.path);
        if (address) navigate(address);
    });
    const runs = new RunController({ request: ws.request.bind(ws), onEvent: ws.onEvent.bind(ws), resultsJson: rest.resultsJson.bind(rest),
        onResubscribe: ws.onResubscribe.bind(ws) });
    const plots = new PlotArea(runs, session.units, () => savePlots(localStorage, summary.id, plots.layout()),
        () => signalSources(store.model));
    void session.units.load();
    const runPanel = new RunPanel(runs, plots, opened.model.system.simulation, () => sinkVariables(store.model),
        (changed) => store.execute(new SetSimulationSettings(changed)));
    store.subscribe(() => runPanel.showModelSettings(store.model.system.simulation));

    // edit errors in words, in a box over the canvas that nothing clips (MessageArea.ts)
    const messages = new MessageArea();
    const reportError = (e: unknown) => messages.error(e);
    const picker = h('div', { class: 'variable-picker', hidden: true, role: 'menu' });
    const showVariables = (ref: PortRef, at: { x: number; y: number }) => {
        const vars = portVariables(store.model, store.path, ref);
        if (!vars.ok) {
            messages.note(vars.reason);
            return;
        }
        const ordered = [...vars.variables].sort((a, b) => Number(primaryVariables.has(b.name)) - Number(primaryVariables.has(a.name)));
        picker.replaceChildren(h('div', { class: 'picker-title' }, `Plot ${ref.component}.${ref.port}`),
            ...ordered.map((v) => h('button', {
                role: 'menuitem', 'data-variable': `${vars.base}#${v.name}`,
                onclick: () => { plots.addVariable(`${vars.base}#${v.name}`, `${vars.label} ${v.name}`, v.unit); picker.hidden = true; },
            }, `${v.name}${v.unit ? ` [${v.unit}]` : ''}`)));
        picker.style.left = `${Math.min(at.x + 8, innerWidth - 220)}px`;
        picker.style.top = `${Math.min(at.y + 8, innerHeight - 240)}px`;
        picker.hidden = false;
    };
    const closePicker = (e: PointerEvent) => { if (!picker.contains(e.target as Node)) picker.hidden = true; };
    document.addEventListener('pointerdown', closePicker, true);

    const menu = new ContextMenu();
    const help = new ShortcutHelp();
    const canvas = new CanvasView(store, {
        onPortClick: showVariables,
        onComponentDoubleClick: () => panel.focusName(),
        onContextMenu: (target, client) => {
            picker.hidden = true;
            const { items, label } = menuFor(menuContext, target);
            menu.open(items, client, label);
        },
        allows: (edit) => permissions.allows(edit),
    });
    canvas.element.append(messages.element);

    // playback of a run of the history on the animated diagram (src/animation/), plots marking the time
    const animation = new DiagramAnimation(canvas, store);
    const playback = new PlaybackBar({
        animation,
        setPlotTime: (time) => plots.setPlaybackTime(time),
        // only what the run logged is asked for (a recorded live session logs what it recorded)
        load: async (run, names) => {
            const logged = new Set(await rest.loggedVariables(run.jobId));
            await runs.ensure(names.filter((n) => logged.has(n)), [run]);
        },
        changes: async (run) => (await rest.job(run.jobId)).live?.changes ?? [],
    });
    canvas.element.append(playback.element);
    // entering or leaving a subsystem shows other lines and parts: their values are loaded
    let playbackPath = '';
    store.subscribe(() => {
        const path = store.path.join('$');
        if (path === playbackPath) return;
        playbackPath = path;
        playback.refresh().catch((e) => toast(`Playback: ${errorText(e)}`, 'error'));
    });
    const playBack = (job: JobInfo) => {
        runs.choose(job, plots.allVariables())
            .then(() => {
                const run = runs.generations.find((r) => r.jobId === job.id);
                return run ? playback.open(run) : undefined;
            })
            .catch((e) => toast(`Playback: ${errorText(e)}`, 'error'));
    };

    // ---- actions shared by keys, buttons, the panel and the context menus (EditorActions.ts) ----
    // the parameter panel on a component, its first field that takes input in focus
    const focusParameters = () => {
        const field = panel.element.querySelector<HTMLInputElement>('input[name^="param-"]:not([readonly])')
            ?? panel.element.querySelector<HTMLInputElement>('input[name="component-name"]');
        field?.focus();
        field?.select();
    };
    const editor = new EditorActions({
        store, canvas, catalogue,
        report: reportError,
        note: (message) => messages.note(message),
        openParameters: focusParameters,
        allows: (edit) => permissions.allows(edit),
    });
    const actions = {
        rotate: () => void editor.rotate(1),
        flip: () => void editor.flip('horizontal'),
        remove: () => void editor.remove(),
        group: () => void editor.group(),
        ungroup: () => void editor.ungroup(),
        toggleParameterPorts: () => editor.toggleParameterPorts(),
        parameterPortsShown: (name: string) => canvas.parameterPorts.shownFor(store.path, name),
        plotPort: (ref: PortRef, anchor: HTMLElement) => {
            const r = anchor.getBoundingClientRect();
            showVariables(ref, { x: r.left - 200, y: r.top });
        },
        addLiveControl: (name: string) => void live.addControlFor(name),
    };
    const menuContext: MenuContext = {
        actions: editor, store, canvas,
        plot: (variable, label, unit) => plots.addVariable(variable, label, unit),
        showHelp: () => help.open(),
        addLiveControl: (name) => void live.addControlFor(name),
    };
    const panel = new ParameterPanel(store, actions, permissions);
    const parameterPortsButton = h('button', {
        onclick: () => canvas.parameterPorts.showEverywhere(!canvas.parameterPorts.shownEverywhere),
        'aria-pressed': 'false', 'data-testid': 'show-parameter-ports', title: 'Show the parameter ports of every component',
    }, 'Show parameter ports');
    canvas.parameterPorts.subscribe(() => {
        parameterPortsButton.setAttribute('aria-pressed', String(canvas.parameterPorts.shownEverywhere));
        panel.render();
    });


    // the study panel (src/studies/), made once and kept: it follows a running study over this socket
    const studies = new StudyPanel({ rest, ws, store, modelId: () => summary.id,
        latestRun: () => (runs.current?.state === 'done' ? { jobId: runs.current.jobId } : null) });

    // ---- saving ----
    // the server says whether the user may change the model (examples: admin only)
    let writable = (summary as { writable?: boolean }).writable
        ?? (session.user?.role === 'admin' || (summary.owner.id === session.user?.id && !summary.is_example));
    const isOwner = () => writable;
    const save = async (): Promise<boolean> => {
        try {
            await store.idle();
            const asCopy = !isOwner();
            const reply = await ws.request('model.save', asCopy ? { as_copy: true, name: summary.name } : {});
            store.markSaved();
            if (reply.model_id !== summary.id) {
                writable = true;
                summary = { ...summary, id: reply.model_id, name: reply.name, is_example: false, owner: { id: session.user!.id, username: session.user!.username } };
                navigate(`#/model/${reply.model_id}`, true);
                // the own copy is no assignment's copy any more
                if (back.note) {
                    back = { href: back.href, label: back.label };
                    headerKey = '';
                }
                toast(`Saved as your own copy "${reply.name}"`);
                // the copy's runs from now on, not the example's; its plot windows are these
                void historyPanel.reload();
                savePlots(localStorage, summary.id, plots.layout());
            } else {
                toast('Saved');
            }
            renderHeader();
            return true;
        } catch (e) {
            reportError(e);
            return false;
        }
    };

    // ---- header, breadcrumb ----
    const header = h('header', { class: 'editor-header' });
    const breadcrumb = h('nav', { class: 'breadcrumb', 'aria-label': 'Subsystem path' });
    const undoButton = h('button', { onclick: () => store.undo().catch(reportError), 'data-testid': 'undo', title: 'Undo (Ctrl+Z)' }, '↶ Undo');
    const redoButton = h('button', { onclick: () => store.redo().catch(reportError), 'data-testid': 'redo', title: 'Redo (Ctrl+Y)' }, '↷ Redo');
    const saveButton = h('button', { class: 'primary', onclick: () => void save(), 'data-testid': 'save', title: 'Save (Ctrl+S)' }, 'Save');
    const dirtyMark = h('span', { class: 'dirty-mark', 'data-testid': 'dirty', title: 'Unsaved changes' });
    // Runs on every store change (a click that selects, a move): only what changed is written,
    // since rewriting the header and the breadcrumb makes the browser lay out the whole page,
    // the canvas's drawing with it.
    let headerKey = '';
    let breadcrumbKey = '';
    const renderHeader = () => {
        const dirty = store.dirty;
        const set = <T extends object, K extends keyof T>(target: T, key: K, value: T[K]) => { if (target[key] !== value) target[key] = value; };
        set(dirtyMark, 'textContent', dirty ? '● unsaved' : '');
        set(dirtyMark.dataset, 'dirty', String(dirty));
        set(saveButton, 'textContent', isOwner() ? 'Save' : 'Save as my copy');
        set(undoButton, 'disabled', !store.history.canUndo);
        set(redoButton, 'disabled', !store.history.canRedo);
        set(undoButton, 'title', store.history.undoLabel ? `Undo ${store.history.undoLabel} (Ctrl+Z)` : 'Undo (Ctrl+Z)');
        set(redoButton, 'title', store.history.redoLabel ? `Redo ${store.history.redoLabel} (Ctrl+Y)` : 'Redo (Ctrl+Y)');
        const nextHeaderKey = JSON.stringify([summary.name, summary.is_example]);
        if (nextHeaderKey !== headerKey) {
            headerKey = nextHeaderKey;
            header.replaceChildren(
                h('a', { href: back.href, class: 'back' }, `← ${back.label}`),
                h('h1', { class: 'model-name', 'data-testid': 'model-name' }, summary.name),
                summary.is_example ? h('span', { class: 'badge' }, 'example') : '',
                back.note ? h('span', { class: 'editor-note', 'data-testid': 'editor-note', title: back.note }, back.note) : '',
                dirtyMark, saveButton, undoButton, redoButton,
                h('button', { onclick: () => canvas.zoomBy(1.25), title: 'Zoom in' }, '+'),
                h('button', { onclick: () => canvas.zoomBy(0.8), title: 'Zoom out' }, '−'),
                h('button', { onclick: () => canvas.fit(), title: 'Show all' }, 'Fit'),
                parameterPortsButton,
                h('button', {
                    onclick: () => help.toggle(), 'aria-label': 'Keyboard shortcuts', title: 'Keyboard shortcuts (?)', 'data-testid': 'shortcuts-button',
                }, '?'),
                h('button', {
                    onclick: async () => {
                        try { downloadText(`${summary.name}.hmf`, await rest.downloadHmf(summary.id), 'application/xml'); } catch (e) { reportError(e); }
                    },
                    title: 'Download the saved model as .hmf',
                }, 'Download .hmf'),
                h('button', {
                    onclick: () => void studies.open(), title: 'Sweeps, sensitivity analyses and optimisations of this model', 'data-testid': 'study-button',
                }, 'Study…'),
                h('button', {
                    onclick: () => openFmuDialog(rest, { id: summary.id, unsaved: store.dirty }),
                    title: 'Export the saved model as an FMI 2.0 co-simulation FMU',
                    'data-testid': 'download-fmu',
                }, 'Download FMU…'));
        }
        const path = store.path;
        const nextBreadcrumbKey = JSON.stringify([store.model.system.name, ...path]);
        if (nextBreadcrumbKey !== breadcrumbKey) {
            breadcrumbKey = nextBreadcrumbKey;
            breadcrumb.replaceChildren(
                h('button', { class: 'crumb', onclick: () => store.enterSystem([]) }, store.model.system.name),
                ...path.flatMap((name, i) => [h('span', { class: 'sep' }, '›'),
                    h('button', { class: 'crumb', onclick: () => store.enterSystem(path.slice(0, i + 1)) }, name)]));
        }
    };
    store.subscribe(renderHeader);
    renderHeader();

    const canvasHint = h('div', { class: 'canvas-hint muted' }, 'Drag: select · Space+drag, middle drag: pan · Wheel: zoom · Port to port: connect · Drag a line: reshape · Click a port: plot · Right click: menu · ?: keys');
    // a locked copy takes no new components: no palette; an assignment's instructions sit at the right
    const editorBody = h('div', { class: `editor-body${assignment ? ' with-instructions' : ''}${permissions.locked ? ' locked-copy' : ''}` },
        permissions.allows('add') ? createPalette(catalogue, (type) => void canvas.addComponent(type, canvas.viewCentre())) : null,
        h('section', { class: 'canvas-column' }, breadcrumb, canvas.element, canvasHint),
        panel.element,
        assignment ? instructionsPanel(assignment) : null);
    const historyPanel = new HistoryPanel(rest, runs, { modelId: () => summary.id, username: () => session.user?.username,
        parameters: () => parameterTexts(store.model), plotted: () => plots.allVariables(), playBack });
    // live mode (src/live/): its toolbar beside ▶ Run, its controls on the drawing
    const live = new LiveMode({
        transport: { request: ws.request.bind(ws), onLive: ws.onLive.bind(ws), onStatus: ws.onStatus.bind(ws) },
        store, canvas, plots, modelId: () => summary.id, defaultVariables: () => sinkVariables(store.model),
        recorded: () => void historyPanel.reload(), editable: () => permissions.allows('system-parameters'), reportError,
        goingLive: () => playback.close(),
        // a teacher (or an administrator) may share a session with a class they teach
        classes: session.user?.role === 'teacher' || session.user?.role === 'admin' ? () => session.labs.listClasses() : undefined,
    });
    runPanel.element.querySelector('[data-testid="cancel"]')?.after(live.bar.element);
    live.attachDiagram(animation);
    const runArea = h('section', { class: 'run-area' }, runPanel.element, h('div', { class: 'run-body' }, historyPanel.element, plots.element));
    const layout = h('main', { class: 'editor' }, header, editorBody, runArea, picker);
    // the drawing and the run area share the height as the user last left them
    layout.insertBefore(createSplitter({
        upper: editorBody, lower: runArea, storage: localStorage, storageKey: 'tlmhub.runAreaShare', initial: 0.5,
        label: 'Resize the drawing and the plots',
        apply: (share) => {
            layout.style.setProperty('--drawing-rows', `${1 - share}fr`);
            layout.style.setProperty('--run-rows', `${share}fr`);
        },
    }), runArea);
    root.replaceChildren(layout);
    // (render fits the view to the model)
    canvas.render();
    // The plots and the runs as they were when the model was last open here (a reload, say).
    const savedPlots = loadPlots(localStorage, summary.id, (name) => isLoggedVariable(store.model, name));
    if (savedPlots.length > 0) plots.openLayout(savedPlots);
    else plots.addWindow();
    rest.runHistory(summary.id, HISTORY_PAGE).then((history) => runs.restore(history),
        (e) => toast(`Earlier runs: ${errorText(e)}`, 'error'));
    layout.addEventListener('editor-error', (e) => messages.show((e as CustomEvent<string>).detail, 'error'));

    // ---- keys ----
    // the keys' table (shortcuts.ts) is also what the menus and the help panel show
    const onShortcut: Record<ShortcutId, () => void> = {
        'save': () => void save(),
        'undo': () => { store.undo().catch(reportError); },
        'redo': () => { store.redo().catch(reportError); },
        'copy': () => void editor.copy(),
        'cut': () => void editor.cut(),
        'paste': () => void editor.paste(),
        'select-all': () => editor.selectAll(),
        'group': () => void editor.group(),
        'delete': () => void editor.remove(),
        'rotate-right': () => void editor.rotate(1),
        'rotate-left': () => void editor.rotate(-1),
        'flip-horizontal': () => void editor.flip('horizontal'),
        'flip-vertical': () => void editor.flip('vertical'),
        'parameter-ports': () => editor.toggleParameterPorts(),
        'all-parameter-ports': () => editor.toggleAllParameterPorts(),
        'names': () => editor.toggleNames(),
        'open': () => {
            const [only, ...more] = editor.selected();
            if (!only || more.length > 0) return;
            if (only.system) editor.enter(only.name); else editor.openParameters(only.name);
        },
        'fit': () => editor.fit(),
        'deselect': () => { canvas.selectedConnection = null; store.select([]); },
        'menu': () => {
            const { target, client } = canvas.contextTargetOfSelection();
            const { items, label } = menuFor(menuContext, target);
            menu.open(items, client, label);
        },
        'help': () => help.toggle(),
    };
    const onKey = (e: KeyboardEvent) => {
        const target = e.target as HTMLElement;
        const focus = target.closest('input, textarea, select, [contenteditable="true"]') ? 'field'
            : target.closest('button, a, [role="menuitem"], [role="tab"], .plot-window') ? 'control' : 'canvas';
        const shortcut = shortcutFor(e, focus);
        if (!shortcut) return;
        // the browser's own meaning of these keys (save page, select the page's text …) is not wanted here
        if (shortcut.id !== 'copy' || store.selection.size > 0) e.preventDefault();
        onShortcut[shortcut.id]();
    };
    document.addEventListener('keydown', onKey);
    const onBeforeUnload = (e: BeforeUnloadEvent) => {
        if (!store.dirty) return;
        e.preventDefault();
        e.returnValue = '';
    };
    window.addEventListener('beforeunload', onBeforeUnload);
    ws.onClose((reason) => {
        if (reason !== 'auth') toast('Connection to the server lost: reload the page (unsaved changes are lost).', 'error');
        // the server closes the sockets of a session it ended: then /auth/me answers 401 and the
        // session goes back to the login page
        void session.rest.me().catch(() => undefined);
    });

    // ---- reconnecting: the open model is the socket's, so a new socket opens it again ----
    ws.onReconnect(async () => {
        const reopened = await ws.request('model.open', { model_id: summary.id });
        if (reopened.writable !== undefined) writable = reopened.writable;
        // the unsaved edits lived in the lost socket's session on the server: they are sent again
        if (!await store.reopen(reopened.model)) {
            toast('The connection to the server was lost: the saved model is open again; changes since the last save could not be restored.', 'error');
        }
        renderHeader();
    });
    const connection = h('span', { class: 'connection-status', 'data-testid': 'connection-status', 'data-state': ws.status, role: 'status' });
    let connectionTimer: ReturnType<typeof setTimeout> | undefined;
    const showConnection = (status: typeof ws.status) => {
        clearTimeout(connectionTimer);
        connection.dataset.state = status;
        connection.textContent = status === 'reconnecting' ? 'reconnecting…' : status === 'closed' ? 'disconnected' : status === 'connected' ? 'connected' : '';
        // "connected" is shown for a moment after a reconnect, then the status steps aside
        if (status === 'connected') connectionTimer = setTimeout(() => { connection.textContent = ''; }, 4000);
    };
    connection.textContent = '';
    const offStatus = ws.onStatus(showConnection);
    runPanel.element.append(connection);

    // the browser tests' handle, only in their build (vite build --mode e2e)
    const testHandle = window as unknown as { __tlmhub?: unknown };
    if (import.meta.env.MODE === 'e2e') testHandle.__tlmhub = { store, canvas, runs, plots, ws, animation, playback, live };

    return {
        dirty: () => store.dirty,
        showPath,
        dispose: () => {
            document.removeEventListener('keydown', onKey);
            menu.close(false);
            help.dispose();
            messages.dispose();
            document.removeEventListener('pointerdown', closePicker, true);
            window.removeEventListener('beforeunload', onBeforeUnload);
            offStatus();
            clearTimeout(connectionTimer);
            delete testHandle.__tlmhub;
            playback.close();
            canvas.dispose();
            plots.dispose();
            historyPanel.dispose();
            studies.dispose();
            live.dispose();
            runs.dispose();
            ws.close();
        },
    };
}
