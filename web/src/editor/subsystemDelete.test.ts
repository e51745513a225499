import { describe, expect, it } from 'vitest';
import { EditorStore } from './EditorStore';
import { AddComponent, Connect, GroupComponents, RemoveComponents, SetParameter, SetSystemParameter } from './commands';
import { FakeServer } from '../testing/FakeServer';
import { systemAt } from '../model/modelState';
import type { Connection, Pose } from '../protocol/types';

const at = (x: number, y: number): Pose => ({ x, y, angle: 0, flipped: false });
const ends = (connections: Connection[]) => connections.map((c) => `${c.from.component}.${c.from.port}-${c.to.component}.${c.to.port}`).sort();
/** The connections as pairs of ports, whichever end is `from` (a power line either way round). */
const links = (connections: Connection[]) => connections.map((c) => [`${c.from.component}.${c.from.port}`, `${c.to.component}.${c.to.port}`].sort().join(' - ')).sort();

// A - [B - C] - D, with B and C grouped into a subsystem that has a parameter of its own.
async function modelWithSubsystem() {
    const server = new FakeServer();
    const store = new EditorStore(server.model, server.handle);
    const add = (name: string, x: number) => store.execute(new AddComponent([], 'HydraulicVolume', name, at(x, 0)));
    for (const [name, x] of [['A', 0], ['B', 200], ['C', 300], ['D', 500]] as const) await add(name, x);
    await store.execute(new Connect([], { component: 'A', port: 'P2' }, { component: 'B', port: 'P1' }));
    await store.execute(new Connect([], { component: 'B', port: 'P2' }, { component: 'C', port: 'P1' }));
    await store.execute(new Connect([], { component: 'C', port: 'P2' }, { component: 'D', port: 'P1' }));
    await store.execute(new SetParameter([], 'B', 'V', '0.25'));
    const group = new GroupComponents([], ['B', 'C'], 'Sub');
    await store.execute(group);
    await store.execute(new SetSystemParameter(['Sub'], { name: 'scale', value: '3', type: 'double', unit: '', description: 'a gain' }));
    return { server, store };
}

describe('deleting a subsystem', () => {
    it('is undone: the subsystem comes back with its content, parameters, ports and connections', async () => {
        const { server, store } = await modelWithSubsystem();
        const before = structuredClone(systemAt(store.model, ['Sub'])!);
        const outsideBefore = ends(store.model.system.connections);

        await store.execute(new RemoveComponents([], ['Sub']));
        expect(store.model.system.components.map((c) => c.name)).toEqual(['A', 'D']);
        expect(store.history.canUndo).toBe(true);

        await store.undo();
        const sub = systemAt(store.model, ['Sub']);
        expect(sub).not.toBeNull();
        expect(sub!.components.map((c) => c.name).sort()).toEqual(['B', 'C']);
        expect(sub!.components.find((c) => c.name === 'B')!.parameters.find((p) => p.name === 'V')!.value).toBe('0.25');
        expect(sub!.parameters).toEqual(before.parameters);
        expect(ends(sub!.connections)).toEqual(ends(before.connections));
        expect(sub!.ports.map((p) => [p.name, p.pose])).toEqual(before.ports.map((p) => [p.name, p.pose]));
        expect(ends(store.model.system.connections)).toEqual(outsideBefore);
        // the local model is the server's
        expect(store.model).toEqual(server.model);

        // and redo deletes it again
        await store.redo();
        expect(systemAt(store.model, ['Sub'])).toBeNull();
    });

    it('is undone with a subsystem inside it, whose content, parameters and connections come back too', async () => {
        const { server, store } = await modelWithSubsystem();
        await store.execute(new GroupComponents(['Sub'], ['B'], 'Inner'));
        await store.execute(new SetSystemParameter(['Sub', 'Inner'], { name: 'depth', value: '2', type: 'double', unit: '', description: '' }));
        const before = structuredClone(systemAt(store.model, ['Sub'])!);
        const innerBefore = structuredClone(systemAt(store.model, ['Sub', 'Inner'])!);
        const outsideBefore = ends(store.model.system.connections);

        await store.execute(new RemoveComponents([], ['Sub']));
        expect(systemAt(store.model, ['Sub'])).toBeNull();
        await store.undo();

        const sub = systemAt(store.model, ['Sub'])!;
        const inner = systemAt(store.model, ['Sub', 'Inner']);
        expect(inner).not.toBeNull();
        expect(sub.components.map((c) => c.name).sort()).toEqual(before.components.map((c) => c.name).sort());
        expect(inner!.components.map((c) => c.name)).toEqual(['B']);
        expect(inner!.components[0].parameters.find((p) => p.name === 'V')!.value).toBe('0.25');
        expect(inner!.parameters).toEqual(innerBefore.parameters);
        expect(ends(inner!.connections)).toEqual(ends(innerBefore.connections));
        expect(links(sub.connections)).toEqual(links(before.connections));
        expect(ends(store.model.system.connections)).toEqual(outsideBefore);
        expect(store.model).toEqual(server.model);
    });
});
