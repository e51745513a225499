// A new socket opens the saved model: the store sends its unsaved commands again, so the
// server's model is the one on screen again, with the history kept.
import { describe, expect, it } from 'vitest';
import { EditorStore } from './EditorStore';
import { AddComponent, Connect, MoveComponents, SetSimulationSettings } from './commands';
import { FakeServer } from '../testing/FakeServer';
import type { Transport } from './EditorStore';
import type { Model } from '../protocol/types';

const at = (x: number, y: number) => ({ x, y, angle: 0, flipped: false });

/** A store whose transport can be switched to a new server session, as after a reconnect. */
async function saved() {
    let server = new FakeServer();
    const transport: Transport = (request) => server.handle(request);
    const store = new EditorStore(structuredClone(server.model), transport);
    await store.execute(new AddComponent([], 'SignalStep', 'Step', at(0, 0)));
    await store.execute(new AddComponent([], 'SignalGain', 'Gain', at(100, 0)));
    store.markSaved();
    const savedModel: Model = structuredClone(server.model);
    /** The socket is lost: a new session opens the saved model. */
    const reconnect = () => {
        server = new FakeServer(savedModel);
        return structuredClone(savedModel);
    };
    return { store, reconnect, server: () => server };
}

describe('EditorStore.reopen', () => {
    it('nothing unsaved: the reopened model is the one on screen, undo still works', async () => {
        const { store, reconnect, server } = await saved();
        expect(await store.reopen(reconnect())).toBe(true);
        expect(store.dirty).toBe(false);
        expect(store.model).toEqual(server().model);
        await store.undo();
        expect(server().model.system.components.map((c) => c.name)).toEqual(['Step']);
    });

    it('sends the unsaved edits again on the new session, keeping dirty state and undo', async () => {
        const { store, reconnect, server } = await saved();
        await store.execute(new Connect([], { component: 'Step', port: 'out' }, { component: 'Gain', port: 'in' }));
        await store.execute(new MoveComponents([], [{ name: 'Gain', from: at(100, 0), to: at(150, 20) }]));
        await store.execute(new SetSimulationSettings({ stop: 1000 }));
        const onScreen = structuredClone(store.model);
        expect(await store.reopen(reconnect())).toBe(true);
        expect(server().model).toEqual(onScreen);
        expect(store.model).toEqual(onScreen);
        expect(store.dirty).toBe(true);
        await store.undo();   // settings
        await store.undo();   // move
        expect(server().model.system.components[1].pose).toEqual(at(100, 0));
        expect(store.model).toEqual(server().model);
    });

    it('edits after undoing past the save point cannot be replayed: the saved model, a fresh history', async () => {
        const { store, reconnect, server } = await saved();
        await store.undo();   // add Gain, which was saved
        await store.execute(new AddComponent([], 'SignalGain', 'Other', at(0, 50)));
        expect(await store.reopen(reconnect())).toBe(false);
        expect(store.model).toEqual(server().model);
        expect(store.model.system.components.map((c) => c.name)).toEqual(['Step', 'Gain']);
        expect(store.dirty).toBe(false);
        expect(store.history.canUndo).toBe(false);
    });
});
