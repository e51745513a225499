import { describe, expect, it } from 'vitest';
import { EditorStore } from './EditorStore';
import { GroupComponents, UngroupSubsystem } from './commands';
import type { Transport } from './EditorStore';
import { FakeServer } from '../testing/FakeServer';

const model = new FakeServer().model;

// A transport that records the requests and answers as the server would.
function recording() {
    const sent: { type: string }[] = [];
    const transport = async (request: { type: string }): Promise<Record<string, unknown>> => {
        sent.push(request);
        if (request.type === 'model.group') return { name: 'Subsystem_1' };
        if (request.type === 'model.ungroup') return { names: ['A', 'B_1'] };
        if (request.type === 'model.get') return { model };
        return {};
    };
    return { sent, store: new EditorStore(model, transport as Transport) };
}

describe('grouping commands', () => {
    it('group is undone by ungrouping the name the server chose', async () => {
        const { sent, store } = recording();
        const command = new GroupComponents(['Sub'], ['A', 'B']);
        await store.execute(command);
        expect(command.subsystemName).toBe('Subsystem_1');
        expect(store.history.canUndo).toBe(true);
        await store.undo();
        expect(sent.map((r) => r.type)).toEqual(['model.group', 'model.get', 'model.ungroup', 'model.get']);
        expect(sent[0]).toMatchObject({ system: ['Sub'], names: ['A', 'B'], name: 'Subsystem' });
        expect(sent[2]).toMatchObject({ system: ['Sub'], name: 'Subsystem_1' });
    });

    it('ungroup is undone by grouping the names the server reported', async () => {
        const { sent, store } = recording();
        const command = new UngroupSubsystem([], 'Valves');
        await store.execute(command);
        expect(command.movedNames).toEqual(['A', 'B_1']);
        await store.undo();
        expect(sent[2]).toMatchObject({ type: 'model.group', names: ['A', 'B_1'], name: 'Valves' });
    });
});
