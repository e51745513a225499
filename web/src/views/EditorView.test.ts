// @vitest-environment jsdom
// Leaving the editor leaves nothing behind: every listener the page put on document and
// window is taken off again, every resize observer disconnected, and the canvas no longer
// follows the store.
import { afterEach, describe, expect, it, vi } from 'vitest';
import { renderEditor } from './EditorView';
import { CanvasView } from '../editor/CanvasView';
import { EditorStore } from '../editor/EditorStore';
import { emptyModel } from '../testing/FakeServer';
import type { Session } from '../app/Session';
import { UnitPreferences } from '../run/unitPreferences';

// uPlot asks for the pixel ratio's media query when it is loaded; jsdom has none
vi.hoisted(() => {
    window.matchMedia = (() => ({ addEventListener: () => undefined, removeEventListener: () => undefined })) as unknown as typeof window.matchMedia;
});

const model = emptyModel('Leaks');
model.system.components.push({
    name: 'Gain', type: 'SignalGain', kind: 'S', pose: { x: 0, y: 0, angle: 0, flipped: false },
    ports: [{ name: 'in', kind: 'read', node_type: 'NodeSignal', connected: false, multiport: false },
        { name: 'out', kind: 'write', node_type: 'NodeSignal', connected: false, multiport: false }],
    parameters: [],
} as unknown as (typeof model.system.components)[number]);

/** A socket that greets and answers model.open with the model above. */
class FakeSocket {
    onopen: ((ev: unknown) => void) | null = null;
    onmessage: ((ev: { data: unknown }) => void) | null = null;
    onclose: ((ev: unknown) => void) | null = null;
    onerror: ((ev: unknown) => void) | null = null;
    constructor() { queueMicrotask(() => this.receive({ type: 'hello', protocol: 'tlmhub.v1' })); }
    send(data: string): void {
        const { id } = JSON.parse(data) as { id: number };
        queueMicrotask(() => this.receive({ type: 'reply', id, data: { model_id: 1, model } }));
    }
    close(): void { /* the client drops the socket itself */ }
    private receive(msg: unknown): void { this.onmessage?.({ data: JSON.stringify(msg) }); }
}

/** Counts the listeners on `target` that were added and not removed again. */
function watchListeners(target: EventTarget): () => string[] {
    const live = new Map<string, number>();
    const key = (type: string, listener: unknown, options: unknown) =>
        `${type}:${String(typeof options === 'boolean' ? options : (options as { capture?: boolean } | undefined)?.capture ?? false)}:${listenerId(listener)}`;
    const add = target.addEventListener.bind(target);
    const remove = target.removeEventListener.bind(target);
    vi.spyOn(target, 'addEventListener').mockImplementation((type, listener, options) => {
        live.set(key(type, listener, options), (live.get(key(type, listener, options)) ?? 0) + 1);
        add(type, listener, options);
    });
    vi.spyOn(target, 'removeEventListener').mockImplementation((type, listener, options) => {
        const k = key(type, listener, options);
        if (live.has(k)) live.set(k, live.get(k)! - 1);
        remove(type, listener, options);
    });
    return () => [...live].filter(([, n]) => n > 0).map(([k]) => k.split(':')[0]);
}

const ids = new WeakMap<object, number>();
let lastId = 0;
function listenerId(listener: unknown): number {
    if (!ids.has(listener as object)) ids.set(listener as object, ++lastId);
    return ids.get(listener as object)!;
}

describe('leaving the editor', () => {
    afterEach(() => vi.restoreAllMocks());

    it('removes its document and window listeners, disconnects its observers, stops the canvas', async () => {
        const observers: { disconnected: boolean }[] = [];
        vi.stubGlobal('ResizeObserver', class {
            private readonly state = { disconnected: false };
            constructor() { observers.push(this.state); }
            observe(): void { /* sizes do not change in the test */ }
            disconnect(): void { this.state.disconnected = true; }
        });
        vi.stubGlobal('WebSocket', FakeSocket);
        const onDocument = watchListeners(document);
        const onWindow = watchListeners(window);
        const session = {
            token: 't', user: { id: 1, username: 'alice', role: 'user' },
            rest: {
                getModel: () => Promise.resolve({ id: 1, name: 'Leaks', is_example: false, owner: { id: 1, username: 'alice' }, model }),
                components: () => Promise.resolve([]),
                me: () => Promise.resolve({}),
                resultsJson: () => Promise.resolve({}),
                runHistory: () => Promise.resolve([]),
            },
            units: new UnitPreferences({
                preferences: () => Promise.resolve({ units: {} }),
                setPreferences: (p) => Promise.resolve(p),
            }, () => undefined),
        } as unknown as Session;

        const page = await renderEditor(document.body, session, 1, () => undefined);
        expect(document.querySelector('[data-name="Gain"]')).not.toBeNull();
        expect(onDocument().length + onWindow().length).toBeGreaterThan(0);
        expect(observers.length).toBeGreaterThan(0);

        page.dispose();
        expect(onDocument()).toEqual([]);
        expect(onWindow()).toEqual([]);
        expect(observers.filter((o) => !o.disconnected)).toEqual([]);
        vi.unstubAllGlobals();
    });

    it('a disposed canvas no longer draws the store\'s changes', () => {
        vi.stubGlobal('ResizeObserver', class { observe(): void { /* unused */ } disconnect(): void { /* unused */ } });
        const store = new EditorStore(structuredClone(model), () => Promise.resolve({}));
        const canvas = new CanvasView(store, { onPortClick: () => undefined, onComponentDoubleClick: () => undefined });
        const render = vi.spyOn(canvas, 'render');
        store.select(['Gain']);
        expect(render).toHaveBeenCalledTimes(1);
        canvas.dispose();
        store.select([]);
        expect(render).toHaveBeenCalledTimes(1);
        vi.unstubAllGlobals();
    });
});
