// Pure functions over ModelJson: find a (sub)system by path and apply the server's replies to
// edit requests, so the local model always equals what the server holds.
import type { Component, Connection, Model, PortRef, System } from '../protocol/types';
import type { ReplyData, RequestFields } from '../protocol/requests.generated';

export type SystemPath = string[];

/** The system at `path` (names of subsystem components from the root), or null. */
export function systemAt(model: Model, path: SystemPath): System | null {
    let system: System = model.system;
    for (const name of path) {
        const sub = system.components.find((c) => c.name === name)?.system;
        if (!sub) return null;
        system = sub;
    }
    return system;
}

export function findComponent(system: System, name: string): Component | undefined {
    return system.components.find((c) => c.name === name);
}

/** A name not used by any component or system port of `system`, based on `wanted`. */
export function uniqueName(system: System, wanted: string, taken: Iterable<string> = []): string {
    const used = new Set<string>([...system.components.map((c) => c.name), ...system.ports.map((p) => p.name), ...taken]);
    const base = sanitizeName(wanted);
    if (!used.has(base)) return base;
    const stem = base.replace(/_\d+$/, '');
    for (let i = 1; ; ++i) {
        const candidate = `${stem}_${i}`;
        if (!used.has(candidate)) return candidate;
    }
}

/** Hopsan names: letters, digits and underscores. */
export function sanitizeName(name: string): string {
    const cleaned = name.trim().replace(/[^A-Za-z0-9_]/g, '_');
    return cleaned === '' ? 'Component' : cleaned;
}

export function sameRef(a: PortRef, b: PortRef): boolean {
    return a.component === b.component && a.port === b.port;
}

/** Whether connection `c` joins ports `a` and `b`, in either order. */
export function joins(c: { from: PortRef; to: PortRef }, a: PortRef, b: PortRef): boolean {
    return (sameRef(c.from, a) && sameRef(c.to, b)) || (sameRef(c.from, b) && sameRef(c.to, a));
}

export function connectionTouches(c: Connection, component: string): boolean {
    return c.from.component === component || c.to.component === component;
}

export function connectionsOf(system: System, component: string): Connection[] {
    return system.connections.filter((c) => connectionTouches(c, component));
}

// Copy-on-write of the system at `path`: returns a new model in which `change` replaced it.
function updateSystem(model: Model, path: SystemPath, change: (s: System) => System): Model {
    const rebuild = (system: System, depth: number): System => {
        if (depth === path.length) return change(system);
        return {
            ...system,
            components: system.components.map((c) =>
                c.name === path[depth] && c.system ? { ...c, system: rebuild(c.system, depth + 1) } : c),
        };
    };
    return { ...model, system: rebuild(model.system, 0) };
}

// Port "connected" flags follow the connection list.
function refreshConnected(system: System): System {
    const used = new Set<string>();
    for (const c of system.connections) {
        used.add(`${c.from.component}.${c.from.port}`);
        used.add(`${c.to.component}.${c.to.port}`);
    }
    return {
        ...system,
        components: system.components.map((comp) => {
            const ports = comp.ports.map((p) => {
                const connected = used.has(`${comp.name}.${p.name}`);
                return p.connected === connected ? p : { ...p, connected };
            });
            return ports.some((p, i) => p !== comp.ports[i]) ? { ...comp, ports } : comp;
        }),
    };
}

function mapComponent(system: System, name: string, change: (c: Component) => Component): System {
    return { ...system, components: system.components.map((c) => (c.name === name ? change(c) : c)) };
}

/** The request types that read or change the open model. */
export type EditType = 'model.get' | 'model.settings' | 'model.controls' | 'component.add' | 'component.remove' | 'component.rename'
    | 'component.move' | 'connect' | 'disconnect' | 'connection.route' | 'parameter.get' | 'parameter.set' | 'sysparam.set'
    | 'sysparam.remove' | 'model.group' | 'model.ungroup';
/** An edit request as the editor sends it: the message type and the request's fields. */
export type EditRequestOf<T extends EditType> = { type: T } & RequestFields<T>;
export type EditRequest = { [T in EditType]: EditRequestOf<T> }[EditType];

type Apply<T extends EditType> = (model: Model, request: EditRequestOf<T>, reply: ReplyData<T>) => Model;
const unchanged = (model: Model): Model => model;

// One entry per request type: the model after the server accepted the request and answered.
const appliers: { [T in EditType]: Apply<T> } = {
    'model.get': (_model, _request, reply) => reply.model,
    'model.settings': (model, _request, reply) => ({ ...model, system: { ...model.system, simulation: reply.simulation } }),
    // as the server sends the model: the root has live_controls only when it has any
    'model.controls': (model, _request, reply) => {
        const { live_controls: _old, ...system } = model.system;
        return { ...model, system: reply.controls.length ? { ...system, live_controls: reply.controls } : system };
    },
    'component.add': (model, request, reply) =>
        updateSystem(model, request.system ?? [], (s) => ({ ...s, components: [...s.components, reply.component] })),
    'component.remove': (model, request) => updateSystem(model, request.system ?? [], (s) => refreshConnected({
        ...s,
        components: s.components.filter((c) => c.name !== request.name),
        connections: s.connections.filter((c) => !connectionTouches(c, request.name)),
    })),
    'component.rename': (model, request, reply) => {
        const from = request.name;
        const to = reply.name;
        const rename = (ref: PortRef): PortRef => (ref.component === from ? { ...ref, component: to } : ref);
        return updateSystem(model, request.system ?? [], (s) => ({
            ...s,
            components: s.components.map((c) => (c.name === from ? { ...c, name: to } : c)),
            connections: s.connections.map((c) => ({ ...c, from: rename(c.from), to: rename(c.to) })),
        }));
    },
    // the name is a component's or a system port's (both are moved by the same request)
    'component.move': (model, request) =>
        updateSystem(model, request.system ?? [], (s) => ({
            ...mapComponent(s, request.name, (c) => ({ ...c, pose: request.pose })),
            ports: s.ports.map((p) => (p.name === request.name ? { ...p, pose: request.pose } : p)),
        })),
    'connect': (model, request, reply) =>
        updateSystem(model, request.system ?? [], (s) => refreshConnected({ ...s, connections: [...s.connections, reply.connection] })),
    'disconnect': (model, request) => {
        const a = request.from;
        const b = request.to;
        return updateSystem(model, request.system ?? [], (s) => refreshConnected({
            ...s,
            connections: s.connections.filter((c) => !joins(c, a, b)),
        }));
    },
    // the reply gives the points from the request's `from`; the model keeps its own from -> to
    'connection.route': (model, request, reply) => updateSystem(model, request.system ?? [], (s) => ({
        ...s,
        connections: s.connections.map((c) => {
            if (!joins(c, reply.connection.from, reply.connection.to)) return c;
            const same = sameRef(c.from, reply.connection.from);
            return { ...c, points: same ? reply.connection.points : [...reply.connection.points].reverse() };
        }),
    })),
    'parameter.get': unchanged,
    'parameter.set': (model, request, reply) =>
        updateSystem(model, request.system ?? [], (s) => mapComponent(s, request.component, (c) => ({
            ...c,
            parameters: c.parameters.map((p) => (p.name === reply.parameter.name ? reply.parameter : p)),
        }))),
    'sysparam.set': (model, request, reply) => updateSystem(model, request.system ?? [], (s) => {
        const parameter = reply.parameter;
        const exists = s.parameters.some((p) => p.name === parameter.name);
        return {
            ...s,
            parameters: exists
                ? s.parameters.map((p) => (p.name === parameter.name ? parameter : p))
                : [...s.parameters, parameter],
        };
    }),
    'sysparam.remove': (model, request) => updateSystem(model, request.system ?? [], (s) => ({
        ...s,
        parameters: s.parameters.filter((p) => p.name !== request.name),
    })),
    // grouping changes the system in more places than its reply says: the editor reloads the model
    'model.group': unchanged,
    'model.ungroup': unchanged,
};

/** The model after the server accepted `request` and answered with `reply` (the reply's data). */
export function applyEdit<T extends EditType>(model: Model, request: EditRequestOf<T>, reply: ReplyData<T>): Model {
    const apply: Apply<T> = appliers[request.type];
    return apply(model, request, reply);
}
