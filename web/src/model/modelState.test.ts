import { describe, expect, it } from 'vitest';
import { applyEdit, systemAt, uniqueName } from './modelState';
import { emptyModel } from '../testing/FakeServer';
import type { Component, Model } from '../protocol/types';

function gain(name: string): Component {
    return {
        name, type: 'SignalGain', kind: 'S', pose: { x: 0, y: 0, angle: 0, flipped: false },
        ports: [{ name: 'in', node_type: 'NodeSignal', kind: 'read', multiport: false, connected: false },
            { name: 'out', node_type: 'NodeSignal', kind: 'write', multiport: false, connected: false }],
        parameters: [{ name: 'k#Value', value: '1', unit: '', description: '', type: 'double' }],
    };
}

function withTwoGains(): Model {
    let m = emptyModel();
    m = applyEdit(m, { type: 'component.add', component_type: 'SignalGain' }, { component: gain('A') });
    m = applyEdit(m, { type: 'component.add', component_type: 'SignalGain' }, { component: gain('B') });
    return m;
}

describe('applyEdit', () => {
    it('adds the component of the reply to the root', () => {
        const m = withTwoGains();
        expect(m.system.components.map((c) => c.name)).toEqual(['A', 'B']);
    });

    it('does not change the model it was given', () => {
        const before = withTwoGains();
        const copy = structuredClone(before);
        applyEdit(before, { type: 'component.remove', name: 'A' }, {});
        expect(before).toEqual(copy);
    });

    it('connect marks both ports connected and disconnect clears them', () => {
        const from = { component: 'A', port: 'out' };
        const to = { component: 'B', port: 'in' };
        let m = applyEdit(withTwoGains(), { type: 'connect', from, to }, { connection: { from, to, points: [] } });
        expect(m.system.connections).toHaveLength(1);
        expect(m.system.components[0].ports[1].connected).toBe(true);
        expect(m.system.components[1].ports[0].connected).toBe(true);
        m = applyEdit(m, { type: 'disconnect', from: to, to: from }, {});
        expect(m.system.connections).toHaveLength(0);
        expect(m.system.components[1].ports[0].connected).toBe(false);
    });

    it('removing a component removes its connections', () => {
        const from = { component: 'A', port: 'out' };
        const to = { component: 'B', port: 'in' };
        let m = applyEdit(withTwoGains(), { type: 'connect', from, to }, { connection: { from, to, points: [] } });
        m = applyEdit(m, { type: 'component.remove', name: 'A' }, {});
        expect(m.system.connections).toEqual([]);
        expect(m.system.components[0].ports[0].connected).toBe(false);
    });

    it('rename uses the name the server chose and renames connection ends', () => {
        const from = { component: 'A', port: 'out' };
        const to = { component: 'B', port: 'in' };
        let m = applyEdit(withTwoGains(), { type: 'connect', from, to }, { connection: { from, to, points: [] } });
        m = applyEdit(m, { type: 'component.rename', name: 'A', new_name: 'B' }, { name: 'B_1' });
        expect(m.system.components.map((c) => c.name)).toEqual(['B_1', 'B']);
        expect(m.system.connections[0].from.component).toBe('B_1');
    });

    it('parameter.set takes the parameter of the reply', () => {
        const m = applyEdit(withTwoGains(), { type: 'parameter.set', component: 'B', parameter: 'k#Value', value: '2*x' },
            { parameter: { name: 'k#Value', value: '2*x', unit: '', description: '', type: 'double' } });
        expect(m.system.components[1].parameters[0].value).toBe('2*x');
        expect(m.system.components[0].parameters[0].value).toBe('1');
    });

    it('sysparam.set adds then replaces', () => {
        const p = { name: 'x', value: '3', type: 'double' as const, unit: 'm', description: '' };
        let m = applyEdit(emptyModel(), { type: 'sysparam.set', name: p.name, value: p.value }, { parameter: p });
        m = applyEdit(m, { type: 'sysparam.set', name: p.name, value: '4' }, { parameter: { ...p, value: '4' } });
        expect(m.system.parameters).toEqual([{ ...p, value: '4' }]);
    });

    it('edits inside a subsystem reach only that subsystem', () => {
        const sub: Component = { ...gain('Sub'), type: 'Subsystem', kind: 'system', ports: [], parameters: [], system: { ...emptyModel('Sub').system, simulation: undefined } };
        let m = applyEdit(emptyModel(), { type: 'component.add', component_type: 'Subsystem' }, { component: sub });
        m = applyEdit(m, { type: 'component.add', system: ['Sub'], component_type: 'SignalGain' }, { component: gain('Inner') });
        expect(m.system.components.map((c) => c.name)).toEqual(['Sub']);
        expect(systemAt(m, ['Sub'])!.components.map((c) => c.name)).toEqual(['Inner']);
        m = applyEdit(m, { type: 'component.move', system: ['Sub'], name: 'Inner', pose: { x: 5, y: 6, angle: 90, flipped: true } }, {});
        expect(systemAt(m, ['Sub'])!.components[0].pose).toEqual({ x: 5, y: 6, angle: 90, flipped: true });
        expect(systemAt(m, ['Nope'])).toBeNull();
    });
});

describe('uniqueName', () => {
    it('keeps a free name and numbers a taken one', () => {
        const m = withTwoGains();
        expect(uniqueName(m.system, 'C')).toBe('C');
        expect(uniqueName(m.system, 'A')).toBe('A_1');
        expect(uniqueName(m.system, 'my gain!')).toBe('my_gain_');
    });
});
