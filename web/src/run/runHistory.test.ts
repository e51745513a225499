import { describe, expect, it } from 'vitest';
import { isLoggedVariable, loadPlots, plotsKey, restorableRuns, savePlots, type SavedPlots } from './runHistory';
import type { Component, JobInfo, Model, Port } from '../protocol/types';

const job = (id: number, state: JobInfo['state'], resultsDropped = false): JobInfo => ({
    id, model_id: 4, state, progress: 1, error: '', created_at: 0, started_at: 0, finished_at: 1, steps: 100,
    settings: { start: 0, step: 0.001, stop: 1, log_samples: 0 }, name: '', pinned: false, results_dropped: resultsDropped,
});

/** A Storage over a plain map (jsdom's localStorage is shared between tests). */
function memoryStorage(initial: Record<string, string> = {}): Storage {
    const items = new Map(Object.entries(initial));
    return {
        get length() { return items.size; },
        clear: () => items.clear(),
        getItem: (key) => items.get(key) ?? null,
        key: (i) => [...items.keys()][i] ?? null,
        removeItem: (key) => { items.delete(key); },
        setItem: (key, value) => { items.set(key, value); },
    };
}

const port = (name: string, node: string): Port => ({ name, kind: 'power', node_type: node, connected: true, multiport: false });
const comp = (name: string, ports: Port[], system?: Model['system']): Component =>
    ({ name, type: system ? 'Subsystem' : 'MechanicTranslationalMass', kind: system ? 'system' : 'C', pose: { x: 0, y: 0, angle: 0, flipped: false }, ports, parameters: [], system });
const system = (name: string, components: Component[]): Model['system'] =>
    ({ name, type: 'Subsystem', timestep: 1, inherit_timestep: true, parameters: [], ports: [], components, connections: [] });
// Mass.P2 at the root; Sub$Cyl.P1 inside a subsystem
const model: Model = {
    name: 'M',
    system: system('M', [comp('Mass', [port('P2', 'NodeMechanic')]), comp('Sub', [], system('Sub', [comp('Cyl', [port('P1', 'NodeHydraulic')])]))]),
};

describe('restorableRuns', () => {
    it('lists the runs that ended well, newest first', () => {
        const picked = restorableRuns([job(12, 'failed'), job(11, 'cancelled'), job(10, 'done'), job(8, 'running'), job(7, 'done'), job(3, 'done')]);
        expect(picked.map((j) => j.id)).toEqual([10, 7, 3]);
    });

    it('skips runs whose results were dropped and does not rely on the order of the page', () => {
        const picked = restorableRuns([job(5, 'done'), job(9, 'done', true), job(6, 'done'), job(2, 'done')]);
        expect(picked.map((j) => j.id)).toEqual([6, 5, 2]);
    });

    it('has nothing to show for a history without a finished run', () => {
        expect(restorableRuns([])).toEqual([]);
        expect(restorableRuns([job(4, 'interrupted'), job(3, 'dead')])).toEqual([]);
        expect(restorableRuns([job(4, 'done')])).toEqual([job(4, 'done')]);
    });
});

describe('saved plot windows', () => {
    const position = { name: 'Mass#P2#Position', label: 'Mass.P2 Position', unit: 'm' };
    const windows: SavedPlots = [
        { variables: [position, { name: 'Mass#P2#Velocity', label: 'Mass.P2 Velocity', unit: 'm/s' }] },
        { variables: [] },
        { variables: [{ name: 'Sub$Cyl#P1#Pressure', label: 'Sub$Cyl.P1 Pressure', unit: 'Pa' }], zoom: { x: [1.5, 2.25] } },
    ];

    it('come back per model, without empty windows', () => {
        const storage = memoryStorage();
        savePlots(storage, 4, windows);
        expect(storage.getItem(plotsKey(4))).not.toBeNull();
        expect(loadPlots(storage, 4, () => true)).toEqual([windows[0], windows[2]]);
        expect(loadPlots(storage, 5, () => true)).toEqual([]);
    });

    it('are forgotten when no window shows a variable', () => {
        const storage = memoryStorage();
        savePlots(storage, 4, windows);
        savePlots(storage, 4, [{ variables: [] }]);
        expect(storage.getItem(plotsKey(4))).toBeNull();
    });

    it('drop variables the model no longer has, windows left empty, and what is not in the saved form', () => {
        const storage = memoryStorage({
            [plotsKey(4)]: JSON.stringify([
                [{ name: 'Gone#P1#Pressure', label: 'Gone.P1 Pressure', unit: 'Pa' }],
                [{ name: 'Mass#P2#Position', label: 'Mass.P2 Position', unit: 'm' }, { name: 7 }, 'Mass#P2#Velocity', null],
                'not a window',
            ]),
            [plotsKey(5)]: '{not json',
            [plotsKey(6)]: '{"a": 1}',
        });
        const known = (name: string) => isLoggedVariable(model, name);
        expect(loadPlots(storage, 4, known)).toEqual([{ variables: [position] }]);
        expect(loadPlots(storage, 5, known)).toEqual([]);
        expect(loadPlots(storage, 6, known)).toEqual([]);
    });

    it('keep each window\'s zoomed time and y ranges', () => {
        const storage = memoryStorage();
        const zoomed: SavedPlots = [{ variables: [position], zoom: { x: [2, 3.5], y: { m: [-0.1, 0.4] } } }, windows[2]];
        savePlots(storage, 4, zoomed);
        expect(loadPlots(storage, 4, () => true)).toEqual(zoomed);
    });

    it('open windows saved before zooms were kept as before, and drop a zoom not in the saved form', () => {
        const storage = memoryStorage({
            [plotsKey(4)]: JSON.stringify([
                [position],
                { variables: [position], zoom: { x: [3, 1] } },
                { variables: [position], zoom: { x: [1, 3], y: { m: 'all' } } },
                { variables: [position], zoom: { x: [1, 3], y: { m: [0, 1] } } },
            ]),
        });
        expect(loadPlots(storage, 4, () => true)).toEqual([
            { variables: [position] }, { variables: [position] }, { variables: [position] },
            { variables: [position], zoom: { x: [1, 3], y: { m: [0, 1] } } },
        ]);
    });
});

describe('isLoggedVariable', () => {
    it('knows the variables of the model\'s ports, in subsystems too', () => {
        expect(isLoggedVariable(model, 'Mass#P2#Position')).toBe(true);
        expect(isLoggedVariable(model, 'Sub$Cyl#P1#Pressure')).toBe(true);
    });

    it('refuses components, ports and variables the model does not have', () => {
        expect(isLoggedVariable(model, 'Gone#P2#Position')).toBe(false);
        expect(isLoggedVariable(model, 'Mass#P9#Position')).toBe(false);
        expect(isLoggedVariable(model, 'Mass#P2#Pressure')).toBe(false);
        expect(isLoggedVariable(model, 'Cyl#P1#Pressure')).toBe(false);
        expect(isLoggedVariable(model, 'Mass#P2')).toBe(false);
    });
});
