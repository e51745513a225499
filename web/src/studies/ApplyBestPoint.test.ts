import { describe, expect, it } from 'vitest';
import { EditorStore } from '../editor/EditorStore';
import { AddComponent } from '../editor/commands';
import { FakeServer } from '../testing/FakeServer';
import { ApplyBestPoint } from './ApplyBestPoint';
import { parameterNamed, studyParameters } from './studyParameters';

const at = { x: 0, y: 0, angle: 0, flipped: false };

async function setup() {
    const server = new FakeServer();
    const store = new EditorStore(structuredClone(server.model), server.handle);
    await store.execute(new AddComponent([], 'SignalGain', 'GainP', at));
    await store.execute(new AddComponent([], 'SignalGain', 'GainI', at));
    return { server, store };
}
const value = (store: EditorStore, component: string) =>
    store.model.system.components.find((c) => c.name === component)!.parameters.find((p) => p.name === 'k#Value')!.value;

describe('Apply best point', () => {
    it('sets every parameter of the best point as one step that one undo takes back, and redo sets again', async () => {
        const { server, store } = await setup();
        const before = store.history.undoLabel;
        await store.execute(new ApplyBestPoint({ 'GainP.k': 0.018, 'GainI.k': 0.0015 }, 7));
        expect([value(store, 'GainP'), value(store, 'GainI')]).toEqual(['0.018', '0.0015']);
        expect(store.history.undoLabel).toBe('Apply best point of study 7');
        await store.undo();
        expect([value(store, 'GainP'), value(store, 'GainI')]).toEqual(['1', '1']);
        expect(store.history.undoLabel).toBe(before);
        await store.redo();
        expect(value(store, 'GainP')).toBe('0.018');
        expect(store.model).toEqual(server.model);
    });

    it('refuses a parameter the model lacks and changes nothing', async () => {
        const { store } = await setup();
        await expect(store.execute(new ApplyBestPoint({ 'GainP.k': 2, 'Nope.k': 1 }, 3))).rejects.toThrow('The model has no parameter Nope.k');
        expect(value(store, 'GainP')).toBe('1');
    });
});

describe('the model\'s parameters by study name', () => {
    it('names a component parameter without #Value and finds it by either name', async () => {
        const { store } = await setup();
        expect(studyParameters(store.model).map((p) => p.name)).toEqual(['GainP.k', 'GainI.k']);
        expect(parameterNamed(store.model, 'GainI.k#Value')).toMatchObject({ component: 'GainI', parameter: 'k#Value', value: 1 });
    });
});
