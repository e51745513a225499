import { describe, expect, it } from 'vitest';
import { EditorStore } from './EditorStore';
import {
    AddComponent, Connect, copySelection, Disconnect, MoveComponents, Paste, RemoveComponents,
    RenameComponent, SetParameter, SetSimulationSettings, SetSystemParameter,
} from './commands';
import { FakeServer } from '../testing/FakeServer';
import { ApiError } from '../api/ApiError';

const at = (x: number, y: number) => ({ x, y, angle: 0, flipped: false });

// A store talking to a fake server; after every step the local model must equal the server's.
async function setup() {
    const server = new FakeServer();
    const store = new EditorStore(structuredClone(server.model), server.handle);
    await store.execute(new AddComponent([], 'SignalStep', 'Step', at(0, 0)));
    await store.execute(new AddComponent([], 'SignalGain', 'Gain', at(100, 0)));
    await store.execute(new Connect([], { component: 'Step', port: 'out' }, { component: 'Gain', port: 'in' }));
    return { server, store };
}

describe('EditorStore with commands', () => {
    it('keeps the local model equal to the server model', async () => {
        const { server, store } = await setup();
        expect(store.model).toEqual(server.model);
        expect(store.system.connections).toHaveLength(1);
    });

    it('undo and redo of add, connect and move', async () => {
        const { server, store } = await setup();
        await store.execute(new MoveComponents([], [{ name: 'Gain', from: at(100, 0), to: at(150, 20) }]));
        expect(store.system.components[1].pose).toEqual(at(150, 20));
        await store.undo();
        expect(store.system.components[1].pose).toEqual(at(100, 0));
        await store.undo();   // connect
        expect(store.system.connections).toHaveLength(0);
        await store.undo();   // add Gain
        expect(store.system.components.map((c) => c.name)).toEqual(['Step']);
        await store.redo();
        await store.redo();
        expect(store.system.components.map((c) => c.name)).toEqual(['Step', 'Gain']);
        expect(store.system.connections).toHaveLength(1);
        expect(store.model).toEqual(server.model);
    });

    it('undo of a delete restores the component, its changed parameters and its connections', async () => {
        const { server, store } = await setup();
        await store.execute(new SetParameter([], 'Gain', 'k#Value', '7'));
        await store.execute(new RemoveComponents([], ['Gain']));
        expect(store.system.components.map((c) => c.name)).toEqual(['Step']);
        expect(store.system.connections).toHaveLength(0);
        await store.undo();
        const gain = store.system.components.find((c) => c.name === 'Gain')!;
        expect(gain.parameters.find((p) => p.name === 'k#Value')!.value).toBe('7');
        expect(gain.pose).toEqual(at(100, 0));
        expect(store.system.connections).toHaveLength(1);
        expect(store.model.system.components.map((c) => c.name).sort()).toEqual(server.model.system.components.map((c) => c.name).sort());
    });

    it('rename undo goes back to the old name, also when the server picked another name', async () => {
        const { store } = await setup();
        const rename = new RenameComponent([], 'Gain', 'Step');
        await store.execute(rename);
        expect(rename.newName).toBe('Step_1');
        expect(store.system.connections[0].to.component).toBe('Step_1');
        await store.undo();
        expect(store.system.components.map((c) => c.name)).toEqual(['Step', 'Gain']);
    });

    it('a refused command changes neither the model nor the history', async () => {
        const { store } = await setup();
        const before = structuredClone(store.model);
        const undoLabel = store.history.undoLabel;
        const refused = store.execute(new Connect([], { component: 'Step', port: 'out' }, { component: 'Gain', port: 'out' }));
        await expect(refused).rejects.toMatchObject({ code: 'illegal_connection' });
        await expect(refused).rejects.toBeInstanceOf(ApiError);
        expect(store.model).toEqual(before);
        expect(store.history.undoLabel).toBe(undoLabel);
    });

    it('a refused parameter value keeps the old value', async () => {
        const { store } = await setup();
        await expect(store.execute(new SetParameter([], 'Gain', 'k#Value', 'nosuchname'))).rejects.toMatchObject({ code: 'invalid_parameter' });
        expect(store.system.components[1].parameters[0].value).toBe('1');
        await store.execute(new SetSystemParameter([], { name: 'nosuchname', value: '3', type: 'double', unit: '', description: '' }));
        await store.execute(new SetParameter([], 'Gain', 'k#Value', 'nosuchname'));
        expect(store.system.components[1].parameters[0].value).toBe('nosuchname');
        await store.undo();
        expect(store.system.components[1].parameters[0].value).toBe('1');
    });

    it('disconnect can be undone', async () => {
        const { store } = await setup();
        await store.execute(new Disconnect([], { component: 'Step', port: 'out' }, { component: 'Gain', port: 'in' }));
        expect(store.system.connections).toHaveLength(0);
        await store.undo();
        expect(store.system.connections).toHaveLength(1);
    });

    it('paste adds copies with new names and their inner connections; undo removes them', async () => {
        const { store } = await setup();
        const clip = copySelection(store.model, [], ['Step', 'Gain'])!;
        expect(clip.connections).toHaveLength(1);
        const paste = new Paste([], clip);
        await store.execute(paste);
        expect(paste.addedNames).toEqual(['Step_1', 'Gain_1']);
        expect(store.system.connections.map((c) => `${c.from.component}-${c.to.component}`)).toEqual(['Step-Gain', 'Step_1-Gain_1']);
        expect(store.system.components[2].pose).toEqual(at(40, 40));
        await store.undo();
        expect(store.system.components.map((c) => c.name)).toEqual(['Step', 'Gain']);
    });

    it('dirty follows the history: saved, changed, undone back to the saved state', async () => {
        const { store } = await setup();
        expect(store.dirty).toBe(true);
        store.markSaved();
        expect(store.dirty).toBe(false);
        await store.execute(new MoveComponents([], [{ name: 'Step', from: at(0, 0), to: at(10, 0) }]));
        expect(store.dirty).toBe(true);
        await store.undo();
        expect(store.dirty).toBe(false);
        await store.redo();
        expect(store.dirty).toBe(true);
    });

    it('a new command clears the redo stack', async () => {
        const { store } = await setup();
        await store.undo();
        expect(store.history.canRedo).toBe(true);
        await store.execute(new MoveComponents([], [{ name: 'Step', from: at(0, 0), to: at(10, 0) }]));
        expect(store.history.canRedo).toBe(false);
    });

    it('system parameters: a change undoes to the old value, a creation undoes to nothing', async () => {
        const { server, store } = await setup();
        await store.execute(new SetSystemParameter([], { name: 'p', value: '1', type: 'double', unit: '', description: '' }));
        await store.execute(new SetSystemParameter([], { name: 'p', value: '2', type: 'double', unit: '', description: '' }));
        await store.undo();
        expect(store.system.parameters[0].value).toBe('1');
        await store.undo();
        expect(store.system.parameters).toHaveLength(0);
        expect(server.log.at(-1)?.type).toBe('sysparam.remove');
        await store.redo();
        expect(store.system.parameters.map((p) => p.value)).toEqual(['1']);
    });

    it('simulation settings change the model and undo to the previous ones', async () => {
        const { server, store } = await setup();
        await store.execute(new SetSimulationSettings({ stop: 3 }));
        await store.execute(new SetSimulationSettings({ stop: 7, log_samples: 500 }));
        expect(store.model.system.simulation).toMatchObject({ stop: 7, log_samples: 500 });
        expect(server.model.system.simulation).toMatchObject({ stop: 7, log_samples: 500 });
        expect(store.dirty).toBe(true);
        await store.undo();
        expect(store.model.system.simulation).toMatchObject({ stop: 3 });
        expect(server.model.system.simulation).toEqual(store.model.system.simulation);
    });

    it('commands run one after another even when started together', async () => {
        const { server, store } = await setup();
        const moves = [1, 2, 3].map((i) => store.execute(new MoveComponents([], [{ name: 'Step', from: at(0, 0), to: at(i, 0) }])));
        await Promise.all(moves);
        expect(server.log.slice(-3).map((r) => (r.pose as { x: number }).x)).toEqual([1, 2, 3]);
        expect(store.system.components[0].pose.x).toBe(3);
    });

    it('selection drops removed components', async () => {
        const { store } = await setup();
        store.select(['Step', 'Gain']);
        await store.execute(new RemoveComponents([], ['Gain']));
        expect([...store.selection]).toEqual(['Step']);
    });
});
