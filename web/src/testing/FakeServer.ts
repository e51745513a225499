// An in-memory stand-in for the server's edit session, for unit tests: it answers edit
// requests the way the protocol describes (replies and refusals) on its own copy of a model.
import { ApiError } from '../api/ApiError';
import { systemAt, type SystemPath } from '../model/modelState';
import type { Transport } from '../editor/EditorStore';
import type { Component, LiveControl, Model, Param, PortRef, System } from '../protocol/types';

interface TypeInfo { kind: Component['kind']; ports: [string, 'power' | 'read' | 'write', string][]; params: [string, string][] }

export const fakeCatalogue: Record<string, TypeInfo> = {
    SignalStep: { kind: 'S', ports: [['out', 'write', 'NodeSignal']], params: [['y_0#Value', '0'], ['y_A#Value', '1']] },
    SignalGain: { kind: 'S', ports: [['in', 'read', 'NodeSignal'], ['out', 'write', 'NodeSignal']], params: [['k#Value', '1']] },
    HydraulicVolume: { kind: 'C', ports: [['P1', 'power', 'NodeHydraulic'], ['P2', 'power', 'NodeHydraulic']], params: [['V', '0.001']] },
    MechanicTranslationalMass: { kind: 'Q', ports: [['P1', 'power', 'NodeMechanic'], ['P2', 'power', 'NodeMechanic']], params: [['m', '1']] },
    // two valves with the same power ports (replaceable by each other), and a relief valve
    // whose replacement lacks its xv output (a check valve)
    Hydraulic43Valve: {
        kind: 'Q',
        ports: [['PP', 'power', 'NodeHydraulic'], ['PT', 'power', 'NodeHydraulic'], ['PA', 'power', 'NodeHydraulic'], ['PB', 'power', 'NodeHydraulic'],
            ['in', 'read', 'NodeSignal'], ['xv', 'write', 'NodeSignal'], ['x_pa', 'read', 'NodeSignal']],
        params: [['in#Value', '0'], ['xv#Value', '0'], ['x_pa#Value', '-1e-06'], ['omega_h', '100'], ['delta_h', '1']],
    },
    Hydraulic43ValveNeutralToTank: {
        kind: 'Q',
        ports: [['PP', 'power', 'NodeHydraulic'], ['PT', 'power', 'NodeHydraulic'], ['PA', 'power', 'NodeHydraulic'], ['PB', 'power', 'NodeHydraulic'],
            ['xv', 'write', 'NodeSignal'], ['in', 'read', 'NodeSignal'], ['x_pa', 'read', 'NodeSignal'], ['p_c', 'read', 'NodeSignal']],
        params: [['in#Value', '0'], ['xv#Value', '0'], ['x_pa#Value', '-1e-06'], ['p_c#Value', '0.001'], ['omega_h', '100']],
    },
    HydraulicPressureReliefValve: {
        kind: 'Q',
        ports: [['P1', 'power', 'NodeHydraulic'], ['P2', 'power', 'NodeHydraulic'], ['xv', 'write', 'NodeSignal'], ['p_max', 'read', 'NodeSignal']],
        params: [['p_max#Value', '2e7'], ['k_cs', '1e-8']],
    },
    HydraulicCheckValve: {
        kind: 'Q',
        ports: [['P1', 'power', 'NodeHydraulic'], ['P2', 'power', 'NodeHydraulic'], ['K_s', 'read', 'NodeSignal'], ['x', 'write', 'NodeSignal']],
        params: [['K_s#Value', '5e-7']],
    },
    HydraulicTankC: { kind: 'C', ports: [['P1', 'power', 'NodeHydraulic']], params: [['p', '1e5']] },
};

export function emptyModel(name = 'Test'): Model {
    return {
        name,
        system: {
            name, type: 'Subsystem', timestep: 0.001, inherit_timestep: false,
            simulation: { start: 0, step: 0.001, stop: 1, log_samples: 100 },
            parameters: [], ports: [], components: [], connections: [],
        },
    };
}

/** A request as it arrives on the wire: the fake checks its fields as the server does, at run time. */
type WireRequest = { type: string; system?: SystemPath; [field: string]: unknown };

export class FakeServer {
    model: Model;
    readonly log: WireRequest[] = [];

    constructor(model: Model = emptyModel()) {
        this.model = structuredClone(model);
    }

    private system(request: WireRequest): System {
        const s = systemAt(this.model, request.system ?? []);
        if (!s) throw new ApiError('not_found', 'no such system');
        return s;
    }

    private component(system: System, name: string): Component {
        const c = system.components.find((x) => x.name === name);
        if (!c) throw new ApiError('not_found', `no component ${name}`);
        return c;
    }

    /** The transport of an EditorStore in tests; it answers in the protocol's reply shapes. */
    handle: Transport = (request) => this.answer(request as WireRequest) as never;

    private answer = async (request: WireRequest): Promise<Record<string, unknown>> => {
        this.log.push(structuredClone(request));
        const system = this.system(request);
        switch (request.type) {
        case 'component.add': {
            const type = request.component_type as string;
            const info = fakeCatalogue[type];
            if (!info) throw new ApiError('unknown_component_type', `unknown component type ${type}`);
            let name = (request.name as string | undefined) ?? type;
            for (let i = 1; system.components.some((c) => c.name === name); ++i) name = `${request.name ?? type}_${i}`;
            const component: Component = {
                name, type, kind: info.kind,
                pose: (request.pose as Component['pose']) ?? { x: 0, y: 0, angle: 0, flipped: false },
                ports: info.ports.map(([n, kind, node]) => ({ name: n, kind, node_type: node, multiport: false, connected: false })),
                parameters: info.params.map(([n, v]) => ({ name: n, value: v, unit: '', description: '', type: 'double' })),
            };
            system.components.push(component);
            return { component: structuredClone(component) };
        }
        case 'component.remove': {
            const name = request.name as string;
            this.component(system, name);
            system.components = system.components.filter((c) => c.name !== name);
            system.connections = system.connections.filter((c) => c.from.component !== name && c.to.component !== name);
            this.refresh(system);
            return {};
        }
        case 'component.rename': {
            const c = this.component(system, request.name as string);
            let wanted = request.new_name as string;
            for (let i = 1; system.components.some((x) => x.name === wanted && x !== c); ++i) wanted = `${request.new_name}_${i}`;
            for (const conn of system.connections) {
                if (conn.from.component === c.name) conn.from.component = wanted;
                if (conn.to.component === c.name) conn.to.component = wanted;
            }
            c.name = wanted;
            return { name: wanted };
        }
        case 'component.move': {
            const pose = structuredClone(request.pose as Component['pose']);
            const port = system.ports.find((p) => p.name === request.name);
            if (port) port.pose = pose;
            else this.component(system, request.name as string).pose = pose;
            return {};
        }
        case 'model.get':
            return { model: structuredClone(this.model) };
        case 'model.group':
            return { name: this.group(system, request.names as string[], request.name as string, request.pose as Component['pose'] | undefined) };
        case 'connect': {
            const from = request.from as PortRef;
            const to = request.to as PortRef;
            const a = this.component(system, from.component).ports.find((p) => p.name === from.port);
            const b = this.component(system, to.component).ports.find((p) => p.name === to.port);
            if (!a || !b) throw new ApiError('not_found', 'no such port');
            if (a.node_type !== b.node_type) {
                throw new ApiError('illegal_connection', `${from.component}.${from.port} (${a.node_type}) and ${to.component}.${to.port} (${b.node_type}) have different node types`);
            }
            if (a.kind === 'write' && b.kind === 'write') {
                throw new ApiError('illegal_connection', `${from.component}.${from.port} and ${to.component}.${to.port} are both write ports`);
            }
            const connection = { from: { ...from }, to: { ...to }, points: (request.points as [number, number][] | undefined) ?? [] };
            system.connections.push(connection);
            this.refresh(system);
            return { connection: structuredClone(connection) };
        }
        case 'disconnect': {
            const from = request.from as PortRef;
            const to = request.to as PortRef;
            const before = system.connections.length;
            system.connections = system.connections.filter((c) => !(c.from.component === from.component && c.from.port === from.port && c.to.component === to.component && c.to.port === to.port));
            if (system.connections.length === before) throw new ApiError('not_found', 'no such connection');
            this.refresh(system);
            return {};
        }
        case 'connection.route': {
            const from = request.from as PortRef;
            const to = request.to as PortRef;
            const same = (a: PortRef, b: PortRef) => a.component === b.component && a.port === b.port;
            const line = system.connections.find((c) => (same(c.from, from) && same(c.to, to)) || (same(c.from, to) && same(c.to, from)));
            if (!line) throw new ApiError('not_found', 'not connected');
            const points = structuredClone(request.points as [number, number][]);
            line.points = same(line.from, from) ? points : [...points].reverse();
            return { connection: { from: { ...from }, to: { ...to }, points } };
        }
        case 'parameter.set': {
            const c = this.component(system, request.component as string);
            const p = c.parameters.find((x) => x.name === request.parameter);
            if (!p) throw new ApiError('invalid_parameter', `no parameter ${request.parameter}`);
            const value = String(request.value);
            const known = new Set(system.parameters.map((x) => x.name));
            if (!/^-?[0-9.e+-]+$/.test(value) && !known.has(value)) {
                throw new ApiError('invalid_parameter', `${c.name}.${p.name}: unknown name '${value}'`);
            }
            p.value = value;
            return { parameter: structuredClone(p) };
        }
        case 'sysparam.set': {
            const existing = system.parameters.find((x) => x.name === request.name);
            const param = existing ?? { name: request.name as string, value: '', type: 'double', unit: '', description: '' };
            param.value = String(request.value);
            if (request.unit !== undefined) param.unit = request.unit as string;
            if (!existing) system.parameters.push(param as System['parameters'][number]);
            return { parameter: structuredClone(param) };
        }
        case 'model.settings': {
            const current = this.model.system.simulation ?? { start: 0, step: 0.001, stop: 10, log_samples: 2048 };
            const next = { ...current };
            for (const key of ['start', 'step', 'stop', 'log_samples'] as const) {
                if (typeof request[key] === 'number') next[key] = request[key] as number;
            }
            this.model.system.simulation = next;
            return { simulation: structuredClone(next) };
        }
        case 'model.controls': {
            const controls = request.controls as LiveControl[];
            if (controls.length) this.model.system.live_controls = structuredClone(controls);
            else delete this.model.system.live_controls;
            return { controls: structuredClone(controls) };
        }
        case 'sysparam.remove': {
            const index = system.parameters.findIndex((x) => x.name === request.name);
            if (index < 0) throw new ApiError('not_found', `no system parameter '${request.name}'`);
            system.parameters.splice(index, 1);
            return {};
        }
        default:
            throw new ApiError('unknown_message_type', `unknown message type ${request.type}`);
        }
    };

    // Moves `names` into a new subsystem; each inner port with connections leaving the group
    // gets one system port (named after it), as the server's grouping does per node.
    private group(system: System, names: string[], wanted: string, pose: Component['pose'] | undefined): string {
        let name = wanted;
        for (let i = 1; system.components.some((c) => c.name === name); ++i) name = `${wanted}_${i}`;
        const inside = new Set(names);
        const sub: System = {
            name, type: 'Subsystem', timestep: 0.001, inherit_timestep: true, parameters: [], ports: [],
            components: system.components.filter((c) => inside.has(c.name)),
            connections: system.connections.filter((c) => inside.has(c.from.component) && inside.has(c.to.component)),
        };
        const outsideConnections: System['connections'] = [];
        const portOf = new Map<string, string>();
        for (const c of system.connections) {
            const [mine, other] = inside.has(c.from.component) && !inside.has(c.to.component) ? [c.from, c.to]
                : inside.has(c.to.component) && !inside.has(c.from.component) ? [c.to, c.from] : [null, null];
            if (!mine || !other) continue;
            const key = `${mine.component}.${mine.port}`;
            let port = portOf.get(key);
            if (!port) {
                port = mine.port;
                for (let i = 1; sub.ports.some((p) => p.name === port) || sub.components.some((k) => k.name === port); ++i) port = `${mine.port}_${i}`;
                portOf.set(key, port);
                const nodeType = sub.components.find((k) => k.name === mine.component)!.ports.find((p) => p.name === mine.port)!.node_type;
                sub.ports.push({ name: port, node_type: nodeType, pose: { x: 0, y: 0, angle: 0, flipped: false } });
                sub.connections.push({ from: { component: port, port }, to: { ...mine }, points: [] });
            }
            outsideConnections.push({ from: { component: name, port }, to: { ...other }, points: [] });
        }
        const component: Component = {
            name, type: 'Subsystem', kind: 'system', pose: pose ?? { x: 0, y: 0, angle: 0, flipped: false },
            ports: sub.ports.map((p) => ({ name: p.name, kind: 'system', node_type: p.node_type ?? 'NodeHydraulic', multiport: false, connected: true })),
            parameters: [], system: sub,
        };
        system.components = [...system.components.filter((c) => !inside.has(c.name)), component];
        system.connections = [...system.connections.filter((c) => !inside.has(c.from.component) && !inside.has(c.to.component)), ...outsideConnections];
        this.refresh(system);
        return name;
    }

    private refresh(system: System): void {
        for (const c of system.components) {
            for (const p of c.ports) {
                p.connected = system.connections.some((k) => (k.from.component === c.name && k.from.port === p.name) || (k.to.component === c.name && k.to.port === p.name));
            }
        }
    }
}

export function param(component: Component, name: string): Param | undefined {
    return component.parameters.find((p) => p.name === name);
}
