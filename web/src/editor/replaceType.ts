// "Replace with another type": which types may take a component's place, and what of the
// component they keep. The rule (Hopsan's own replacement lists are not in the catalogue):
// - a type qualifies when it has the same power ports as the component (same names, node
//   types, multiport or not), at least one of them, and the same CQS kind, so that it sits in
//   the model's TLM chain where the old one sat; a type without power ports (a signal block)
//   qualifies when all its ports are the same (SignalAdd for SignalSubtract);
// - the new component keeps the name, the pose, every connection whose port the new type has
//   with the same node type and direction, and the value of every parameter of the same name
//   and type. The other connections are removed (undo brings them back).
import type { CatalogueEntry, CataloguePort } from '../protocol/generated';
import type { Component, Connection, Param, Port } from '../protocol/types';
import { displayNameOf } from '../model/appearance';

/** A port as the rule compares them, from a model component or from the catalogue. */
export interface PortShape { name: string; nodeType: string; kind: Port['kind']; multiport: boolean }

export function portShapeOfCatalogue(p: CataloguePort): PortShape {
    const kind: Port['kind'] = p.porttype.startsWith('Power') ? 'power'
        : p.porttype.startsWith('Read') ? 'read'
            : p.porttype.startsWith('Write') ? 'write'
                : 'bidirectional';
    return { name: p.name, nodeType: p.nodetype, kind, multiport: p.porttype.includes('Multi') };
}

export function portShapeOfModel(p: Port): PortShape {
    return { name: p.name, nodeType: p.node_type, kind: p.kind, multiport: p.multiport };
}

const shapeKey = (p: PortShape) => `${p.name}|${p.nodeType}|${p.kind}|${p.multiport ? 'multi' : 'single'}`;

/** The ports the rule compares, as one string: the power ports, or every port of a type without any. */
export function replacementKey(ports: PortShape[]): string {
    const power = ports.filter((p) => p.kind === 'power');
    const compared = power.length > 0 ? power : ports;
    return `${power.length > 0 ? 'power' : 'all'}:${compared.map(shapeKey).sort().join(',')}`;
}

/** The types that may replace `component`, by display name. None for a subsystem. */
export function replacementTypes(component: Component, catalogue: CatalogueEntry[]): CatalogueEntry[] {
    if (component.system || component.kind === 'system') return [];
    const key = replacementKey(component.ports.map(portShapeOfModel));
    if (key === 'all:') return [];   // no ports at all: nothing to keep, nothing to compare
    return catalogue
        .filter((e) => e.type !== component.type && e.kind === component.kind)
        .filter((e) => replacementKey(e.ports.map(portShapeOfCatalogue)) === key)
        .sort((a, b) => displayNameOf(a.type).localeCompare(displayNameOf(b.type)));
}

/** Whether a connection at `port` of the old component may stay at the new one's port of that name. */
export function portKept(port: PortShape, replacementPorts: PortShape[]): boolean {
    const other = replacementPorts.find((p) => p.name === port.name);
    return other !== undefined && other.nodeType === port.nodeType && other.kind === port.kind;
}

export interface ReplacementPlan {
    /** Connections that stay (their port exists on the new type). */
    kept: Connection[];
    /** Connections that go with the old type. */
    dropped: Connection[];
    /** Parameters whose value carries over (same name and type). */
    parameters: Param[];
}

/** What replacing `component` by a type with `ports` and `parameters` keeps. */
export function replacementPlan(component: Component, connections: Connection[],
    ports: PortShape[], parameters: { name: string; type: string }[]): ReplacementPlan {
    const own = new Map(component.ports.map((p) => [p.name, portShapeOfModel(p)]));
    const kept: Connection[] = [];
    const dropped: Connection[] = [];
    for (const c of connections) {
        const ends = [c.from, c.to].filter((r) => r.component === component.name);
        const ok = ends.every((r) => {
            const shape = own.get(r.port);
            return shape !== undefined && portKept(shape, ports);
        });
        (ok ? kept : dropped).push(c);
    }
    const kinds = new Map(parameters.map((p) => [p.name, p.type]));
    return { kept, dropped, parameters: component.parameters.filter((p) => kinds.get(p.name) === p.type) };
}

/** The plan for a catalogue type, in words for the menu: "keeps 6 of 6 connections and 14 parameters". */
export function planSummary(plan: ReplacementPlan): string {
    const total = plan.kept.length + plan.dropped.length;
    const connections = total === 0 ? 'no connections to keep'
        : plan.dropped.length === 0 ? `keeps ${total === 1 ? 'its connection' : `all ${total} connections`}`
            : `keeps ${plan.kept.length} of ${total} connections (drops ${plan.dropped.map((c) => describeEnd(c)).join(', ')})`;
    const n = plan.parameters.length;
    return `${connections}; ${n === 0 ? 'no parameter values carry over' : `${n} parameter value${n === 1 ? '' : 's'} carry over`}`;
}

function describeEnd(c: Connection): string {
    return `${c.from.component}.${c.from.port}–${c.to.component}.${c.to.port}`;
}
