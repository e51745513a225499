import { describe, expect, it } from 'vitest';
import fixture from '../model/componentTypes.fixture.json';
import { portShapeOfCatalogue, replacementKey, replacementPlan, replacementTypes } from './replaceType';
import { EditorStore } from './EditorStore';
import { AddComponent, Connect, ReplaceComponent, SetParameter } from './commands';
import { FakeServer } from '../testing/FakeServer';
import type { CatalogueEntry, Component, Connection } from '../protocol/types';

// `tlmhub-cli components --json` as the server's GET /components gives it; the fixture has no
// CQS kinds, so the hydraulic valves are Q-type here (as in Hopsan) and the rest as noted
interface FixtureEntry { type: string; ports: { name: string; nodetype: string; porttype: string }[]; parameters: string[] }
const KINDS: Record<string, CatalogueEntry['kind']> = { HydraulicVolume: 'C', HydraulicHose: 'C', HydraulicTLMlossless: 'C' };
const catalogue: CatalogueEntry[] = (fixture as FixtureEntry[]).map((e) => ({
    type: e.type,
    kind: KINDS[e.type] ?? (e.type.startsWith('Signal') ? 'S' : 'Q'),
    domain: '',
    ports: e.ports.map((p) => ({ ...p, required: false, description: '' })),
    parameters: e.parameters.map((name) => ({ name, default: '0', type: 'double' as const, unit: '', description: '' })),
}));
const entry = (type: string) => catalogue.find((e) => e.type === type)!;

/** A model component of a catalogue type, with the given ports connected. */
function componentOf(type: string, name: string, connected: string[] = []): Component {
    const e = entry(type);
    return {
        name, type, kind: e.kind, pose: { x: 0, y: 0, angle: 0, flipped: false },
        ports: e.ports.map((p) => {
            const shape = portShapeOfCatalogue(p);
            return { name: p.name, node_type: p.nodetype, kind: shape.kind, multiport: shape.multiport, connected: connected.includes(p.name) };
        }),
        parameters: e.parameters.map((p) => ({ name: p.name, value: '1', unit: '', description: '', type: 'double' as const })),
    };
}

const line = (a: string, b: string): Connection => {
    const [ac, ap] = a.split('.');
    const [bc, bp] = b.split('.');
    return { from: { component: ac, port: ap }, to: { component: bc, port: bp }, points: [] };
};

describe('which types may replace a component', () => {
    it('a 4/3 valve: the other valves with PP, PT, PA, PB (hydraulic, not multiports)', () => {
        const valve = componentOf('Hydraulic43Valve', '4_3_Servo_Valve');
        expect(replacementTypes(valve, catalogue).map((e) => e.type).sort()).toEqual([
            'Hydraulic42DirectionalValve', 'Hydraulic42Valve', 'Hydraulic42Valve2',
            'Hydraulic43ValveNeutralSupplyToTank', 'Hydraulic43ValveNeutralToTank',
        ]);
    });

    it('a pressure relief valve: Q-types with P1 and P2, never a C-type (HydraulicVolume) nor the type itself', () => {
        const types = replacementTypes(componentOf('HydraulicPressureReliefValve', 'Relief'), catalogue).map((e) => e.type);
        expect(types).toContain('HydraulicCheckValve');
        expect(types).toContain('HydraulicPressureReliefValveG');
        expect(types).not.toContain('HydraulicVolume');
        expect(types).not.toContain('HydraulicPressureReliefValve');
        // every one has exactly the relief valve's power ports
        for (const t of types) {
            const power = entry(t).ports.filter((p) => p.porttype.startsWith('Power')).map((p) => p.name).sort();
            expect(power, t).toEqual(['P1', 'P2']);
        }
    });

    it('a multiport is not a single port: a volume with a multiport is no replacement for a two-port one', () => {
        const a = replacementKey([{ name: 'P1', nodeType: 'NodeHydraulic', kind: 'power', multiport: true }]);
        const b = replacementKey([{ name: 'P1', nodeType: 'NodeHydraulic', kind: 'power', multiport: false }]);
        expect(a).not.toBe(b);
    });

    it('a signal block without power ports: the types with all the same ports (SignalAdd for SignalSubtract)', () => {
        const types = replacementTypes(componentOf('SignalSubtract', 'Subtract'), catalogue).map((e) => e.type);
        expect(types).toEqual(expect.arrayContaining(['SignalAdd', 'SignalMultiply', 'SignalDivide']));
        expect(types).not.toContain('SignalGain');
    });

    it('a subsystem has none', () => {
        const sub: Component = { ...componentOf('Hydraulic43Valve', 'Sub'), type: 'Subsystem', kind: 'system' };
        expect(replacementTypes(sub, catalogue)).toEqual([]);
    });
});

describe('what a replacement keeps', () => {
    it('a 4/3 valve replaced by one with neutral to tank keeps all of Position Servo\'s connections and the equal-named parameters', () => {
        const valve = componentOf('Hydraulic43Valve', 'V', ['PP', 'PT', 'PA', 'PB', 'in', 'xv']);
        const lines = [line('Volume.P1', 'V.PP'), line('Tank.P1', 'V.PT'), line('V.PA', 'Cylinder.P1'), line('V.PB', 'Cylinder.P2'),
            line('Add.out', 'V.in'), line('Sink.in', 'V.xv')];
        const target = entry('Hydraulic43ValveNeutralToTank');
        const plan = replacementPlan(valve, lines, target.ports.map(portShapeOfCatalogue), target.parameters);
        expect(plan.kept).toEqual(lines);
        expect(plan.dropped).toEqual([]);
        // every parameter of the 4/3 valve is one of the new type's too (that adds p_c and f_c)
        expect(plan.parameters.map((p) => p.name)).toEqual(valve.parameters.map((p) => p.name));
        expect(plan.parameters.map((p) => p.name)).toEqual(expect.arrayContaining(['in#Value', 'x_pa#Value', 'omega_h', 'delta_h']));
    });

    it('only parameters of the same name and type carry over', () => {
        const valve = componentOf('Hydraulic43Valve', 'V');
        const target = entry('Hydraulic42Valve');
        const typed = target.parameters.map((p) => (p.name === 'C_q#Value' ? { ...p, type: 'integer' as const } : p));
        const names = replacementPlan(valve, [], target.ports.map(portShapeOfCatalogue), typed).parameters.map((p) => p.name);
        expect(names).toContain('rho#Value');
        expect(names).not.toContain('C_q#Value');       // another type
        expect(names).not.toContain('x_pa#Value');      // the 4/2 valve has no x_pa
        expect(names.every((n) => target.parameters.some((p) => p.name === n))).toBe(true);
    });

    it('a connection at a port the new type lacks is dropped', () => {
        const relief = componentOf('HydraulicPressureReliefValve', 'R', ['P1', 'P2', 'xv']);
        const lines = [line('R.P1', 'Volume.P1'), line('Tank.P1', 'R.P2'), line('R.xv', 'Sink.in')];
        const target = entry('HydraulicCheckValve');
        const plan = replacementPlan(relief, lines, target.ports.map(portShapeOfCatalogue), target.parameters);
        expect(plan.kept).toEqual(lines.slice(0, 2));
        expect(plan.dropped).toEqual([lines[2]]);
    });
});

describe('the ReplaceComponent command', () => {
    const at = (x: number, y: number) => ({ x, y, angle: 90, flipped: true });

    async function servoPart() {
        const server = new FakeServer();
        const store = new EditorStore(structuredClone(server.model), server.handle);
        await store.execute(new AddComponent([], 'Hydraulic43Valve', 'Valve', at(100, 50)));
        await store.execute(new AddComponent([], 'HydraulicTankC', 'Tank', at(0, 0)));
        await store.execute(new AddComponent([], 'SignalStep', 'Step', at(0, 100)));
        await store.execute(new AddComponent([], 'SignalGain', 'Gain', at(200, 100)));
        await store.execute(new Connect([], { component: 'Tank', port: 'P1' }, { component: 'Valve', port: 'PT' }));
        await store.execute(new Connect([], { component: 'Step', port: 'out' }, { component: 'Valve', port: 'in' }));
        await store.execute(new Connect([], { component: 'Valve', port: 'xv' }, { component: 'Gain', port: 'in' }));
        await store.execute(new SetParameter([], 'Valve', 'x_pa#Value', '2e-06'));
        await store.execute(new SetParameter([], 'Valve', 'delta_h', '0.5'));
        return { server, store };
    }
    const valve = (store: EditorStore) => store.system.components.find((c) => c.name === 'Valve')!;
    const ends = (store: EditorStore) => store.system.connections.map((c) => `${c.from.component}.${c.from.port}-${c.to.component}.${c.to.port}`).sort();

    it('keeps name, pose, connections and equal-named values; undo brings the old type back as it was; redo again', async () => {
        const { server, store } = await servoPart();
        const before = structuredClone(store.system);
        const command = new ReplaceComponent([], 'Valve', 'Hydraulic43ValveNeutralToTank');
        await store.execute(command);
        expect(command.newName).toBe('Valve');
        expect(valve(store).type).toBe('Hydraulic43ValveNeutralToTank');
        expect(valve(store).pose).toEqual(at(100, 50));
        expect(ends(store)).toEqual(['Step.out-Valve.in', 'Tank.P1-Valve.PT', 'Valve.xv-Gain.in']);
        expect(valve(store).parameters.find((p) => p.name === 'x_pa#Value')!.value).toBe('2e-06');
        expect(store.model).toEqual(server.model);
        expect(store.history.undoLabel).toBe('Replace Valve by Hydraulic43ValveNeutralToTank');

        await store.undo();
        expect(valve(store).type).toBe('Hydraulic43Valve');
        expect(valve(store).parameters.find((p) => p.name === 'delta_h')!.value).toBe('0.5');
        expect(valve(store).pose).toEqual(before.components.find((c) => c.name === 'Valve')!.pose);
        expect(ends(store)).toEqual(['Step.out-Valve.in', 'Tank.P1-Valve.PT', 'Valve.xv-Gain.in']);
        expect(store.model).toEqual(server.model);

        await store.redo();
        expect(valve(store).type).toBe('Hydraulic43ValveNeutralToTank');
        expect(ends(store)).toHaveLength(3);
    });

    it('a connection the new type has no port for goes, and comes back with undo', async () => {
        const server = new FakeServer();
        const store = new EditorStore(structuredClone(server.model), server.handle);
        await store.execute(new AddComponent([], 'HydraulicPressureReliefValve', 'Relief', at(0, 0)));
        await store.execute(new AddComponent([], 'HydraulicTankC', 'Tank', at(50, 0)));
        await store.execute(new AddComponent([], 'SignalGain', 'Gain', at(50, 50)));
        await store.execute(new Connect([], { component: 'Relief', port: 'P2' }, { component: 'Tank', port: 'P1' }));
        await store.execute(new Connect([], { component: 'Relief', port: 'xv' }, { component: 'Gain', port: 'in' }));
        const command = new ReplaceComponent([], 'Relief', 'HydraulicCheckValve');
        await store.execute(command);
        expect(ends(store)).toEqual(['Relief.P2-Tank.P1']);
        expect(command.droppedConnections.map((c) => c.to.component)).toEqual(['Gain']);
        await store.undo();
        expect(ends(store)).toEqual(['Relief.P2-Tank.P1', 'Relief.xv-Gain.in']);
        expect(store.model).toEqual(server.model);
    });

    it('a step the server refuses puts the old component back and leaves the history as it was', async () => {
        const { server, store } = await servoPart();
        const before = structuredClone(store.model);
        const label = store.history.undoLabel;
        // the server knows no such type: the old valve must come back with its connections
        await expect(store.execute(new ReplaceComponent([], 'Valve', 'NoSuchValve'))).rejects.toMatchObject({ code: 'unknown_component_type' });
        expect(valve(store).type).toBe('Hydraulic43Valve');
        expect(ends(store)).toEqual(ends({ system: before.system } as EditorStore));
        expect(valve(store).parameters).toEqual(before.system.components.find((c) => c.name === 'Valve')!.parameters);
        expect(store.model).toEqual(server.model);
        expect(store.history.undoLabel).toBe(label);
    });
});
