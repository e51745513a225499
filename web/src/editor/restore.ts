// Putting removed things back through edit requests: a component with its parameters, and a
// subsystem with its content. The protocol cannot add system ports, so a subsystem is rebuilt
// the way an ungroup is undone: its content goes back into the parent, joined to the outside
// as its system ports joined them, and is grouped again.
import { sameRef, systemAt, uniqueName, type EditRequestOf, type SystemPath } from '../model/modelState';
import type { EditContext } from './commands';
import type { Component, Connection, Param, PortRef, Pose } from '../protocol/types';

/** What is needed to put a component back: its type, name, pose, parameters. */
export interface ComponentSnapshot { type: string; name: string; pose: Pose; parameters: Param[] }

export function snapshot(c: Component): ComponentSnapshot {
    return { type: c.type, name: c.name, pose: { ...c.pose }, parameters: c.parameters.map((p) => ({ ...p })) };
}

/** Adds a component as in a snapshot: add, then set the parameters whose value differs. */
export async function restoreComponent(ctx: EditContext, path: SystemPath, snap: ComponentSnapshot, name: string): Promise<string> {
    const reply = await ctx.send({ type: 'component.add', system: path, component_type: snap.type, name, pose: snap.pose });
    const added = reply.component;
    for (const p of snap.parameters) {
        const fresh = added.parameters.find((q) => q.name === p.name);
        if (fresh && fresh.value !== p.value) {
            await ctx.send({ type: 'parameter.set', system: path, component: added.name, parameter: p.name, value: p.value });
        }
    }
    return added.name;
}

/** A connection as sent again: its ends and its line's points, when it has any. */
export function connectRequest(path: SystemPath, c: Connection): EditRequestOf<'connect'> {
    return c.points.length > 0
        ? { type: 'connect', system: path, from: c.from, to: c.to, points: c.points }
        : { type: 'connect', system: path, from: c.from, to: c.to };
}

/** A rebuilt subsystem: its name, and the new name of each old system port (the server names them). */
export interface RestoredSubsystem { name: string; ports: Map<string, string> }

const isSystemPort = (ref: PortRef) => ref.component === ref.port;

/**
 * Rebuilds subsystem `sub` (a removed component with its `system`) in the system at `path`.
 * `outside` gives, per old system port, the ports outside it was connected to (as they are named
 * now). A system port with nothing inside it cannot be rebuilt (grouping makes no port for it).
 */
export async function restoreSubsystem(ctx: EditContext, path: SystemPath, sub: Component,
    outside: Map<string, PortRef[]>): Promise<RestoredSubsystem> {
    const inner = sub.system!;
    const here = () => systemAt(ctx.model(), path)!;
    const names = new Map<string, string>();                    // inner name -> name while in the parent
    const nestedPorts = new Map<string, Map<string, string>>();  // nested subsystem -> its port renames
    const mapped = (ref: PortRef): PortRef | null => {
        const component = names.get(ref.component);
        if (!component) return null;
        return { component, port: nestedPorts.get(ref.component)?.get(ref.port) ?? ref.port };
    };
    const touches = (c: Connection, name: string) => c.from.component === name || c.to.component === name;
    const otherEnd = (c: Connection, mine: PortRef): PortRef => (sameRef(c.from, mine) ? c.to : c.from);
    // system ports whose outside ends were joined to a nested subsystem as it was rebuilt
    const delegated = new Set<string>();
    try {
        for (const c of inner.components.filter((k) => !k.system)) {
            names.set(c.name, await restoreComponent(ctx, path, snapshot(c), uniqueName(here(), c.name)));
        }
        for (const n of inner.components.filter((k) => k.system)) {
            // its connections to what is back already; the rest join it when they come back
            // (one led out through this subsystem's own port: to the ports outside it, as it must
            // have a port of its own for that line before it is grouped)
            const ends = new Map<string, PortRef[]>();
            for (const sp of n.system!.ports) {
                const at = { component: n.name, port: sp.name };
                const refs = inner.connections.filter((c) => sameRef(c.from, at) || sameRef(c.to, at))
                    .map((c) => otherEnd(c, at))
                    .flatMap((r): PortRef[] => {
                        if (!isSystemPort(r)) return [mapped(r)].filter((m): m is PortRef => m !== null);
                        if (delegated.has(r.component)) return [];
                        delegated.add(r.component);
                        return outside.get(r.component) ?? [];
                    });
                ends.set(sp.name, refs);
            }
            const rebuilt = await restoreSubsystem(ctx, path, { ...n, name: uniqueName(here(), n.name) }, ends);
            names.set(n.name, rebuilt.name);
            nestedPorts.set(n.name, rebuilt.ports);
        }
        const nested = new Set(inner.components.filter((k) => k.system).map((k) => k.name));
        for (const c of inner.connections) {
            if (isSystemPort(c.from) || isSystemPort(c.to) || nested.has(c.from.component) || nested.has(c.to.component)) continue;
            await ctx.send(connectRequest(path, { ...c, from: mapped(c.from)!, to: mapped(c.to)! }));
        }
        // each system port's node: its inside ends joined to its outside ends
        const hubs = new Map<string, PortRef>();   // old system port -> an inside end, as named inside
        for (const sp of inner.ports) {
            const insideEnds = inner.connections
                .filter((c) => touches(c, sp.name))
                .map((c) => otherEnd(c, { component: sp.name, port: sp.name }));
            // outside ends already joined to a nested subsystem's port are on this node
            const outsideEnds = delegated.has(sp.name) ? [] : (outside.get(sp.name) ?? []);
            const ends = [...insideEnds.map(mapped).filter((r): r is PortRef => r !== null), ...outsideEnds];
            const first = insideEnds[0];
            if (!first || (ends.length < 2 && !delegated.has(sp.name))) continue;
            hubs.set(sp.name, first);
            const hub = ends.find((r) => portKind(ctx, path, r) === 'write') ?? ends[0];
            for (const end of ends) if (end !== hub) await ctx.send({ type: 'connect', system: path, from: hub, to: end });
        }
        const content = [...names.values()];
        const [head, ...rest] = content;
        if (head === undefined) throw new Error(`${sub.name} was empty: an empty subsystem cannot be rebuilt.`);
        const reply = await ctx.send({ type: 'model.group', system: path, names: [head, ...rest], name: sub.name, pose: sub.pose });
        const insidePath = [...path, reply.name];
        for (const [old, now] of names) {
            if (old !== now) await ctx.send({ type: 'component.rename', system: insidePath, name: now, new_name: old });
        }
        await ctx.send({ type: 'model.get' });
        const rebuilt = systemAt(ctx.model(), insidePath)!;
        const ports = new Map<string, string>();
        for (const [old, hub] of hubs) {
            const atHub = { component: hub.component, port: nestedPorts.get(hub.component)?.get(hub.port) ?? hub.port };
            const link = rebuilt.connections.find((c) => (isSystemPort(c.from) || isSystemPort(c.to))
                && [c.from, c.to].some((r) => sameRef(r, atHub)));
            const port = link && (isSystemPort(link.from) ? link.from : link.to).component;
            if (!port) continue;
            ports.set(old, port);
            const pose = inner.ports.find((p) => p.name === old)!.pose;
            await ctx.send({ type: 'component.move', system: insidePath, name: port, pose });
        }
        for (const p of inner.parameters) {
            await ctx.send({ type: 'sysparam.set', system: insidePath, name: p.name, value: p.value, param_type: p.type, unit: p.unit, description: p.description });
        }
        return { name: reply.name, ports };
    } catch (e) {
        // leave the parent as it was before the rebuild started
        for (const name of names.values()) await ctx.send({ type: 'component.remove', system: path, name }).catch(() => undefined);
        throw e;
    }
}

function portKind(ctx: EditContext, path: SystemPath, ref: PortRef): string | undefined {
    return systemAt(ctx.model(), path)?.components.find((c) => c.name === ref.component)?.ports.find((p) => p.name === ref.port)?.kind;
}
