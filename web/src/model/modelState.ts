// Pure functions over ModelJson: find a (sub)system by path and apply the server's replies to
// edit requests, so the local model always equals what the server holds.
import type { Component, Connection, Model, Param, PortRef, Pose, SysParam, System } from '../protocol/types';

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

export interface EditRequest { type: string; system?: SystemPath; [field: string]: unknown }

/**
 * The model after the server accepted `request` and answered with `reply` (the reply's data).
 * Unknown request types leave the model unchanged.
 */
export function applyEdit(model: Model, request: EditRequest, reply: Record<string, unknown>): Model {
    const path = request.system ?? [];
    switch (request.type) {
    case 'model.get':
        return reply.model as Model;
    case 'component.add': {
        const component = reply.component as Component;
        return updateSystem(model, path, (s) => ({ ...s, components: [...s.components, component] }));
    }
    case 'component.remove': {
        const name = request.name as string;
        return updateSystem(model, path, (s) => refreshConnected({
            ...s,
            components: s.components.filter((c) => c.name !== name),
            connections: s.connections.filter((c) => !connectionTouches(c, name)),
        }));
    }
    case 'component.rename': {
        const from = request.name as string;
        const to = (reply.name as string | undefined) ?? (request.new_name as string);
        const rename = (ref: PortRef): PortRef => (ref.component === from ? { ...ref, component: to } : ref);
        return updateSystem(model, path, (s) => ({
            ...s,
            components: s.components.map((c) => (c.name === from ? { ...c, name: to } : c)),
            connections: s.connections.map((c) => ({ ...c, from: rename(c.from), to: rename(c.to) })),
        }));
    }
    case 'component.move': {
        const pose = request.pose as Pose;
        return updateSystem(model, path, (s) => mapComponent(s, request.name as string, (c) => ({ ...c, pose })));
    }
    case 'connect': {
        const connection = (reply.connection as Connection | undefined) ?? {
            from: request.from as PortRef, to: request.to as PortRef, points: [],
        };
        return updateSystem(model, path, (s) => refreshConnected({ ...s, connections: [...s.connections, connection] }));
    }
    case 'disconnect': {
        const a = request.from as PortRef;
        const b = request.to as PortRef;
        return updateSystem(model, path, (s) => refreshConnected({
            ...s,
            connections: s.connections.filter((c) =>
                !((sameRef(c.from, a) && sameRef(c.to, b)) || (sameRef(c.from, b) && sameRef(c.to, a)))),
        }));
    }
    case 'parameter.set': {
        const parameter = reply.parameter as Param;
        return updateSystem(model, path, (s) => mapComponent(s, request.component as string, (c) => ({
            ...c,
            parameters: c.parameters.map((p) => (p.name === parameter.name ? parameter : p)),
        })));
    }
    case 'sysparam.set': {
        const parameter = reply.parameter as SysParam;
        return updateSystem(model, path, (s) => {
            const exists = s.parameters.some((p) => p.name === parameter.name);
            return {
                ...s,
                parameters: exists
                    ? s.parameters.map((p) => (p.name === parameter.name ? parameter : p))
                    : [...s.parameters, parameter],
            };
        });
    }
    case 'model.settings':
        return { ...model, system: { ...model.system, simulation: reply.simulation as Model['system']['simulation'] } };
    case 'sysparam.remove':
        return updateSystem(model, path, (s) => ({
            ...s,
            parameters: s.parameters.filter((p) => p.name !== request.name),
        }));
    default:
        return model;
    }
}
