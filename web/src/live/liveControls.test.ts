import { describe, expect, it } from 'vitest';
import { EditorStore } from '../editor/EditorStore';
import { AddComponent, copySelection, Paste } from '../editor/commands';
import { FakeServer } from '../testing/FakeServer';
import type { SysParam } from '../protocol/types';
import { ChangeLiveControls } from './ChangeLiveControls';
import { CONTROLS_PARAMETER, controlProblem, controlsOf, modelValueOf, withinBounds, type LiveControl } from './liveControls';

const at = (x: number, y: number) => ({ x, y, angle: 0, flipped: false });
const slider: LiveControl = { kind: 'slider', name: 'Step.y_A', min: 0, max: 0.2, x: 100.4, y: 60, path: [] };
const toggle: LiveControl = { kind: 'switch', name: 'Sub$Switch.state', min: 0, max: 1, off: 0, on: 1, x: -20, y: 5, path: ['Sub'] };

async function storeWithStep() {
    const server = new FakeServer();
    const store = new EditorStore(structuredClone(server.model), server.handle);
    await store.execute(new AddComponent([], 'SignalStep', 'Step', at(0, 0)));
    return { server, store };
}

describe('live controls in the model', () => {
    it("are saved in the model's GUI data (model.controls) and read back the same (save and reopen)", async () => {
        const { server, store } = await storeWithStep();
        await store.execute(new ChangeLiveControls([slider, toggle], 'Add live control'));
        expect(server.model.system.live_controls).toEqual([
            { kind: 'slider', name: 'Step.y_A', min: 0, max: 0.2, x: 100, y: 60 },
            { kind: 'switch', name: 'Sub$Switch.state', min: 0, max: 1, off: 0, on: 1, x: -20, y: 5, system: ['Sub'] },
        ]);
        expect(server.model.system.parameters.find((p) => p.name === CONTROLS_PARAMETER)).toBeUndefined();
        // what the server keeps is what a reopened editor (or a copy of the model) starts from
        const reopened = new EditorStore(structuredClone(server.model), server.handle);
        expect(controlsOf(reopened.model)).toEqual([{ ...slider, x: 100 }, toggle]);
        const copied = JSON.parse(JSON.stringify(server.model));
        expect(controlsOf(copied)).toEqual(controlsOf(reopened.model));
    });

    it('moving and removing one are undoable edits', async () => {
        const { store } = await storeWithStep();
        await store.execute(new ChangeLiveControls([slider], 'Add live control'));
        await store.execute(new ChangeLiveControls([{ ...slider, x: 300 }], 'Move live control'));
        expect(store.history.undoLabel).toBe('Move live control');
        expect(controlsOf(store.model)[0].x).toBe(300);
        await store.execute(new ChangeLiveControls([], 'Remove live control'));
        expect(controlsOf(store.model)).toEqual([]);
        await store.undo();
        await store.undo();
        expect(controlsOf(store.model)[0].x).toBe(100);
    });

    it('are not touched by copying and pasting components (they belong to the model)', async () => {
        const { store } = await storeWithStep();
        await store.execute(new ChangeLiveControls([slider], 'Add live control'));
        const clip = copySelection(store.model, [], ['Step'])!;
        await store.execute(new Paste([], clip));
        expect(controlsOf(store.model)).toHaveLength(1);
    });

    it('a model saved with them in the old system parameter shows them, and loses the parameter with the first change (undoable)', async () => {
        const { server } = await storeWithStep();
        const legacy: SysParam = { name: CONTROLS_PARAMETER, value: JSON.stringify([{ ...slider, x: 100 }]), type: 'string', unit: '', description: 'old' };
        server.model.system.parameters.push(legacy);
        const reopened = new EditorStore(structuredClone(server.model), server.handle);
        expect(controlsOf(reopened.model)).toEqual([{ ...slider, x: 100 }]);
        await reopened.execute(new ChangeLiveControls([{ ...slider, x: 300 }], 'Move live control'));
        expect(server.model.system.parameters.some((p) => p.name === CONTROLS_PARAMETER)).toBe(false);
        expect(controlsOf(reopened.model)).toEqual([{ ...slider, x: 300 }]);
        await reopened.undo();
        expect(server.model.system.live_controls).toBeUndefined();
        expect(server.model.system.parameters.find((p) => p.name === CONTROLS_PARAMETER)?.value).toBe(legacy.value);
        expect(controlsOf(reopened.model)).toEqual([{ ...slider, x: 100 }]);
    });

    it('a value edited by hand into something else gives the controls that still make sense', () => {
        const model = (value: string) => ({ name: 'm', system: { ...new FakeServer().model.system, parameters: [{ name: CONTROLS_PARAMETER, type: 'string' as const, unit: '', description: '', value }] } });
        expect(controlsOf(model('not json'))).toEqual([]);
        expect(controlsOf(model('{"kind":"slider"}'))).toEqual([]);
        expect(controlsOf(model('[{"kind":"dial","name":"A.b","min":0,"max":1,"x":0,"y":0},{"kind":"knob","name":"A.b","min":0,"max":1,"x":0,"y":0}]')))
            .toEqual([{ kind: 'knob', name: 'A.b', min: 0, max: 1, x: 0, y: 0, path: [] }]);
    });

    it('show the value the model gives what they set before a session runs (an input by its name)', async () => {
        const { store } = await storeWithStep();
        // (the fake server's step stores its amplitude as y_A#Value = 1)
        expect(modelValueOf(store.model, 'Step.y_A')).toBe(1);
        expect(modelValueOf(store.model, 'Step.nothing')).toBeUndefined();
        expect(modelValueOf(store.model, 'Nobody.y_A')).toBeUndefined();
        expect(modelValueOf(store.model, 'Sub$Step.y_A')).toBeUndefined();
    });

    it('says which numbers cannot be used', () => {
        expect(controlProblem(slider)).toBe('');
        expect(controlProblem({ ...slider, min: 1, max: 1 })).toMatch(/Min must be below max/);
        expect(controlProblem({ ...slider, max: Number.NaN })).toMatch(/number/);
        expect(controlProblem({ ...toggle, on: 0 })).toMatch(/Off and on must differ/);
    });
});

describe('a control within a locked copy\'s bounds', () => {
    it('is cut to the bounds, or takes them when its range lies outside', () => {
        expect(withinBounds(slider, undefined)).toBe(slider);
        expect(withinBounds(slider, {})).toBe(slider);
        expect(withinBounds(slider, { min: 0.05, max: 0.1 })).toMatchObject({ min: 0.05, max: 0.1 });
        expect(withinBounds(slider, { max: 0.1 })).toMatchObject({ min: 0, max: 0.1 });
        expect(withinBounds(slider, { min: 1, max: 2 })).toMatchObject({ min: 1, max: 2 });
        expect(withinBounds(toggle, { min: 0, max: 0.5 })).toMatchObject({ off: 0, on: 0.5, min: 0, max: 0.5 });
    });
});
