// Editor commands: each user action is one object that makes its change through edit requests
// and knows how to take it back (undo = the inverse requests).
import {
    connectionsOf, findComponent, joins, sameRef, systemAt, uniqueName,
    type EditRequestOf, type EditType, type SystemPath,
} from '../model/modelState';
import type { ReplyData } from '../protocol/requests.generated';
import { portShapeOfModel, replacementPlan } from './replaceType';
import { systemPortPlan } from './systemPortPlacement';
import { connectRequest, restoreComponent, restoreSubsystem, snapshot, type ComponentSnapshot } from './restore';
import type { Component, Connection, Model, PortRef, Pose, SimulationSettings, SysParam } from '../protocol/types';

export interface EditContext {
    /** Sends one edit request; the reply is applied to the local model before this resolves. */
    send<T extends EditType>(request: EditRequestOf<T>): Promise<ReplyData<T>>;
    model(): Model;
}

export interface Command {
    readonly label: string;
    /** False when the change cannot be taken back; the history is cleared after it. */
    readonly undoable: boolean;
    do(ctx: EditContext): Promise<void>;
    undo(ctx: EditContext): Promise<void>;
}

export class AddComponent implements Command {
    readonly label: string;
    readonly undoable = true;
    private actualName = '';

    constructor(private readonly path: SystemPath, private readonly type: string,
        private readonly name: string, private readonly pose: Pose) {
        this.label = `Add ${type}`;
    }

    get addedName(): string { return this.actualName; }

    async do(ctx: EditContext): Promise<void> {
        const reply = await ctx.send({ type: 'component.add', system: this.path, component_type: this.type, name: this.name, pose: this.pose });
        this.actualName = reply.component.name;
    }

    async undo(ctx: EditContext): Promise<void> {
        await ctx.send({ type: 'component.remove', system: this.path, name: this.actualName });
    }
}

/**
 * Deletes components, subsystems included; undo puts them back with their parameters and
 * connections (a subsystem with its content, see restore.ts).
 */
export class RemoveComponents implements Command {
    readonly label: string;
    readonly undoable = true;
    private removed: Component[] = [];
    private cut: Connection[] = [];

    constructor(private readonly path: SystemPath, private readonly names: string[]) {
        this.label = names.length === 1 ? `Delete ${names[0]}` : `Delete ${names.length} components`;
    }

    async do(ctx: EditContext): Promise<void> {
        const system = systemAt(ctx.model(), this.path);
        if (!system) throw new Error('no such system');
        this.removed = [];
        this.cut = [];
        for (const name of this.names) {
            const c = findComponent(system, name);
            if (!c) continue;
            this.removed.push(structuredClone(c));
            for (const conn of connectionsOf(system, name)) {
                if (!this.cut.some((k) => sameRef(k.from, conn.from) && sameRef(k.to, conn.to))) this.cut.push(structuredClone(conn));
            }
        }
        for (const c of this.removed) await ctx.send({ type: 'component.remove', system: this.path, name: c.name });
    }

    async undo(ctx: EditContext): Promise<void> {
        for (const c of this.removed.filter((k) => !k.system)) await restoreComponent(ctx, this.path, snapshot(c), c.name);
        // A subsystem joins its outside connections as it is rebuilt; one between two removed
        // subsystems is joined by the later one, with the earlier one's ports as renamed.
        const subsystems = this.removed.filter((k) => k.system);
        const renamedPorts = new Map<string, Map<string, string>>();
        const now = (ref: PortRef): PortRef => ({ component: ref.component, port: renamedPorts.get(ref.component)?.get(ref.port) ?? ref.port });
        const pending = new Set(subsystems.map((k) => k.name));
        for (const sub of subsystems) {
            pending.delete(sub.name);
            const outside = new Map<string, PortRef[]>();
            for (const conn of this.cut) {
                const [mine, other] = conn.from.component === sub.name ? [conn.from, conn.to] : conn.to.component === sub.name ? [conn.to, conn.from] : [null, null];
                if (!mine || !other || pending.has(other.component)) continue;
                outside.set(mine.port, [...(outside.get(mine.port) ?? []), now(other)]);
            }
            const rebuilt = await restoreSubsystem(ctx, this.path, sub, outside);
            renamedPorts.set(sub.name, rebuilt.ports);
        }
        const isSubsystem = new Set(subsystems.map((k) => k.name));
        for (const conn of this.cut) {
            if (isSubsystem.has(conn.from.component) || isSubsystem.has(conn.to.component)) continue;
            await ctx.send(connectRequest(this.path, conn));
        }
    }
}

export class RenameComponent implements Command {
    readonly label: string;
    readonly undoable = true;
    private actual = '';

    constructor(private readonly path: SystemPath, private readonly from: string, private readonly to: string) {
        this.label = `Rename ${from}`;
    }

    get newName(): string { return this.actual; }

    async do(ctx: EditContext): Promise<void> {
        const reply = await ctx.send({ type: 'component.rename', system: this.path, name: this.from, new_name: this.to });
        this.actual = reply.name;
    }

    async undo(ctx: EditContext): Promise<void> {
        await ctx.send({ type: 'component.rename', system: this.path, name: this.actual, new_name: this.from });
    }
}

export interface Move { name: string; from: Pose; to: Pose }

/** A pose turned by quarter turns: +1 a quarter clockwise on screen (Hopsan's "rotate right"), -1 back. */
export function rotatedPose(pose: Pose, quarterTurns: number): Pose {
    return { ...pose, angle: (((pose.angle + 90 * quarterTurns) % 360) + 360) % 360 };
}

/**
 * A pose mirrored left to right on screen (the model's `flipped`), or top to bottom, which is
 * the same mirror turned half a turn, as Hopsan does it.
 */
export function flippedPose(pose: Pose, axis: 'horizontal' | 'vertical'): Pose {
    const mirrored = { ...pose, flipped: !pose.flipped };
    return axis === 'horizontal' ? mirrored : rotatedPose(mirrored, 2);
}

/** Moves, rotations and flips: all are new poses. */
export class MoveComponents implements Command {
    readonly undoable = true;

    constructor(private readonly path: SystemPath, private readonly moves: Move[], readonly label = 'Move') {}

    async do(ctx: EditContext): Promise<void> {
        for (const m of this.moves) await ctx.send({ type: 'component.move', system: this.path, name: m.name, pose: m.to });
    }

    async undo(ctx: EditContext): Promise<void> {
        for (const m of this.moves) await ctx.send({ type: 'component.move', system: this.path, name: m.name, pose: m.from });
    }
}

export class Connect implements Command {
    readonly label = 'Connect';
    readonly undoable = true;

    constructor(private readonly path: SystemPath, private readonly from: PortRef, private readonly to: PortRef) {}

    async do(ctx: EditContext): Promise<void> {
        await ctx.send({ type: 'connect', system: this.path, from: this.from, to: this.to });
    }

    async undo(ctx: EditContext): Promise<void> {
        await ctx.send({ type: 'disconnect', system: this.path, from: this.from, to: this.to });
    }
}

export class Disconnect implements Command {
    readonly label = 'Disconnect';
    readonly undoable = true;
    private removed: Connection | null = null;

    constructor(private readonly path: SystemPath, private readonly from: PortRef, private readonly to: PortRef) {}

    async do(ctx: EditContext): Promise<void> {
        const system = systemAt(ctx.model(), this.path);
        const line = system?.connections.find((c) => joins(c, this.from, this.to));
        this.removed = line ? structuredClone(line) : null;
        await ctx.send({ type: 'disconnect', system: this.path, from: this.from, to: this.to });
    }

    /** Connected again with the line's points. */
    async undo(ctx: EditContext): Promise<void> {
        await ctx.send(connectRequest(this.path, this.removed ?? { from: this.from, to: this.to, points: [] }));
    }
}

/** A line reshaped (segments or corners dragged, corners added or removed): new points from `from` to `to`. */
export class RouteConnection implements Command {
    readonly undoable = true;

    constructor(private readonly path: SystemPath, private readonly from: PortRef, private readonly to: PortRef,
        private readonly before: [number, number][], private readonly after: [number, number][], readonly label = 'Reshape line') {}

    async do(ctx: EditContext): Promise<void> {
        await ctx.send({ type: 'connection.route', system: this.path, from: this.from, to: this.to, points: this.after });
    }

    /** `before` as the model held them, which is from its connection's `from` end. */
    async undo(ctx: EditContext): Promise<void> {
        const system = systemAt(ctx.model(), this.path);
        const line = system?.connections.find((c) => joins(c, this.from, this.to));
        const from = line?.from ?? this.from;
        const to = line?.to ?? this.to;
        await ctx.send({ type: 'connection.route', system: this.path, from, to, points: this.before });
    }
}

export class SetParameter implements Command {
    readonly label: string;
    readonly undoable = true;
    private previous = '';

    constructor(private readonly path: SystemPath, private readonly component: string,
        private readonly parameter: string, private readonly value: string) {
        this.label = `Set ${component}.${parameter}`;
    }

    async do(ctx: EditContext): Promise<void> {
        const system = systemAt(ctx.model(), this.path);
        const old = system && findComponent(system, this.component)?.parameters.find((p) => p.name === this.parameter);
        this.previous = old?.value ?? '';
        await ctx.send({ type: 'parameter.set', system: this.path, component: this.component, parameter: this.parameter, value: this.value });
    }

    async undo(ctx: EditContext): Promise<void> {
        await ctx.send({ type: 'parameter.set', system: this.path, component: this.component, parameter: this.parameter, value: this.previous });
    }
}

// The request's "type" is the message type; the parameter's own type travels as param_type.
export function sysParamRequest(path: SystemPath, p: SysParam): EditRequestOf<'sysparam.set'> {
    return { type: 'sysparam.set', system: path, name: p.name, value: p.value, param_type: p.type, unit: p.unit, description: p.description };
}

export class SetSystemParameter implements Command {
    readonly label: string;
    private previous: SysParam | undefined;

    constructor(private readonly path: SystemPath, private readonly parameter: SysParam) {
        this.label = `Set system parameter ${parameter.name}`;
    }

    readonly undoable = true;

    async do(ctx: EditContext): Promise<void> {
        const system = systemAt(ctx.model(), this.path);
        const old = system?.parameters.find((p) => p.name === this.parameter.name);
        this.previous = old ? { ...old } : undefined;
        await ctx.send(sysParamRequest(this.path, this.parameter));
    }

    async undo(ctx: EditContext): Promise<void> {
        if (this.previous) await ctx.send(sysParamRequest(this.path, this.previous));
        else await ctx.send({ type: 'sysparam.remove', system: this.path, name: this.parameter.name });
    }
}

/** Copied components with the connections among them. */
export interface Clipboard { components: ComponentSnapshot[]; connections: { from: PortRef; to: PortRef }[] }

export function copySelection(model: Model, path: SystemPath, names: Iterable<string>): Clipboard | null {
    const system = systemAt(model, path);
    if (!system) return null;
    const chosen = new Set(names);
    const components = system.components.filter((c) => chosen.has(c.name) && !c.system).map(snapshot);
    if (components.length === 0) return null;
    const kept = new Set(components.map((c) => c.name));
    const connections = system.connections
        .filter((c) => kept.has(c.from.component) && kept.has(c.to.component))
        .map((c) => ({ from: { ...c.from }, to: { ...c.to } }));
    return { components, connections };
}

/** The shift that puts the middle of the clipboard's components at `at` (a paste at the pointer). */
export function offsetTo(clip: Clipboard, at: { x: number; y: number }): { x: number; y: number } {
    const xs = clip.components.map((c) => c.pose.x);
    const ys = clip.components.map((c) => c.pose.y);
    const mid = { x: (Math.min(...xs) + Math.max(...xs)) / 2, y: (Math.min(...ys) + Math.max(...ys)) / 2 };
    return { x: Math.round(at.x - mid.x), y: Math.round(at.y - mid.y) };
}

export class Paste implements Command {
    readonly label = 'Paste';
    readonly undoable = true;
    private added: string[] = [];
    private readonly shift: { x: number; y: number };

    /** `offset`: how far from the copied place, the same on both axes or per axis. */
    constructor(private readonly path: SystemPath, private readonly clip: Clipboard, offset: number | { x: number; y: number } = 40) {
        this.shift = typeof offset === 'number' ? { x: offset, y: offset } : offset;
    }

    get addedNames(): string[] { return [...this.added]; }

    async do(ctx: EditContext): Promise<void> {
        this.added = [];
        const renamed = new Map<string, string>();
        for (const snap of this.clip.components) {
            const system = systemAt(ctx.model(), this.path)!;
            const name = uniqueName(system, snap.name);
            const pose = { ...snap.pose, x: snap.pose.x + this.shift.x, y: snap.pose.y + this.shift.y };
            const actual = await restoreComponent(ctx, this.path, { ...snap, pose }, name);
            renamed.set(snap.name, actual);
            this.added.push(actual);
        }
        const map = (ref: PortRef): PortRef => ({ component: renamed.get(ref.component)!, port: ref.port });
        for (const c of this.clip.connections) {
            await ctx.send({ type: 'connect', system: this.path, from: map(c.from), to: map(c.to) });
        }
    }

    async undo(ctx: EditContext): Promise<void> {
        for (const name of [...this.added].reverse()) await ctx.send({ type: 'component.remove', system: this.path, name });
    }
}

/** The model's own simulation settings (saved with it); undo restores the previous ones. */
export class SetSimulationSettings implements Command {
    readonly label = 'Change simulation settings';
    readonly undoable = true;
    private previous: SimulationSettings | undefined;

    constructor(private readonly settings: Partial<SimulationSettings>) {}

    async do(ctx: EditContext): Promise<void> {
        const current = ctx.model().system.simulation;
        this.previous = current ? { ...current } : undefined;
        await ctx.send({ type: 'model.settings', ...this.settings });
    }

    async undo(ctx: EditContext): Promise<void> {
        if (this.previous) await ctx.send({ type: 'model.settings', ...this.previous });
    }
}

// The server leaves a new subsystem's system ports on one spot; they are moved apart here.
async function placeSystemPorts(ctx: EditContext, path: SystemPath, subsystem: string): Promise<void> {
    const parent = systemAt(ctx.model(), path);
    for (const [name, pose] of parent ? systemPortPlan(parent, subsystem) : []) {
        await ctx.send({ type: 'component.move', system: [...path, subsystem], name, pose });
    }
}

// model.group names at least one component; the editor offers grouping only for a selection.
function nonEmpty(names: string[]): [string, ...string[]] {
    const [first, ...rest] = names;
    if (first === undefined) throw new Error('no components to group');
    return [first, ...rest];
}

/**
 * Moves components into a new subsystem on the server and places its system ports apart
 * (systemPortPlacement.ts); undo ungroups it again.
 */
export class GroupComponents implements Command {
    readonly label: string;
    readonly undoable = true;
    private actual = '';

    constructor(private readonly path: SystemPath, private readonly names: string[], private readonly name = 'Subsystem') {
        this.label = `Group ${names.length} components`;
    }

    get subsystemName(): string { return this.actual; }

    async do(ctx: EditContext): Promise<void> {
        const reply = await ctx.send({ type: 'model.group', system: this.path, names: nonEmpty(this.names), name: this.name });
        this.actual = reply.name;
        await ctx.send({ type: 'model.get' });   // the system changed in more places than one reply says
        await placeSystemPorts(ctx, this.path, this.actual);
    }

    async undo(ctx: EditContext): Promise<void> {
        await ctx.send({ type: 'model.ungroup', system: this.path, name: this.actual });
        await ctx.send({ type: 'model.get' });
    }
}

/** Moves a subsystem's content into the system holding it; undo groups it again. */
export class UngroupSubsystem implements Command {
    readonly label: string;
    readonly undoable = true;
    private moved: string[] = [];

    constructor(private readonly path: SystemPath, private readonly name: string) {
        this.label = `Ungroup ${name}`;
    }

    get movedNames(): string[] { return [...this.moved]; }

    async do(ctx: EditContext): Promise<void> {
        const reply = await ctx.send({ type: 'model.ungroup', system: this.path, name: this.name });
        this.moved = reply.names;
        await ctx.send({ type: 'model.get' });
    }

    async undo(ctx: EditContext): Promise<void> {
        const reply = await ctx.send({ type: 'model.group', system: this.path, names: nonEmpty(this.moved), name: this.name });
        await ctx.send({ type: 'model.get' });
        await placeSystemPorts(ctx, this.path, reply.name);
    }
}

/**
 * Puts a component of another type in a component's place (see replaceType.ts for the rule):
 * same name and pose, the connections whose ports the new type has, the values of parameters
 * of the same name and type. Undo puts the old component back with all its connections. A
 * step the server refuses puts the old one back before the error is reported.
 */
export class ReplaceComponent implements Command {
    readonly label: string;
    readonly undoable = true;
    private old: ComponentSnapshot | null = null;
    private connections: Connection[] = [];
    private actual = '';
    private dropped: Connection[] = [];

    constructor(private readonly path: SystemPath, private readonly name: string, private readonly type: string) {
        this.label = `Replace ${name} by ${type}`;
    }

    /** The new component's name (the old one's, unless the server chose another). */
    get newName(): string { return this.actual; }
    /** The connections the new type had no port for. */
    get droppedConnections(): Connection[] { return [...this.dropped]; }

    async do(ctx: EditContext): Promise<void> {
        const system = systemAt(ctx.model(), this.path);
        const comp = system && findComponent(system, this.name);
        if (!system || !comp) throw new Error(`There is no component ${this.name} here.`);
        if (comp.system) throw new Error(`${this.name} is a subsystem: only components can be replaced by another type.`);
        this.old = snapshot(comp);
        this.connections = connectionsOf(system, this.name).map((c) => structuredClone(c));
        this.actual = '';
        await ctx.send({ type: 'component.remove', system: this.path, name: this.name });
        try {
            const reply = await ctx.send({ type: 'component.add', system: this.path, component_type: this.type, name: this.name, pose: comp.pose });
            const added = reply.component;
            this.actual = added.name;
            const plan = replacementPlan(comp, this.connections, added.ports.map(portShapeOfModel), added.parameters);
            this.dropped = plan.dropped;
            for (const p of plan.parameters) {
                const fresh = added.parameters.find((q) => q.name === p.name);
                if (fresh && fresh.value !== p.value) {
                    await ctx.send({ type: 'parameter.set', system: this.path, component: added.name, parameter: p.name, value: p.value });
                }
            }
            const rename = (ref: PortRef): PortRef => (ref.component === this.name ? { ...ref, component: added.name } : ref);
            for (const c of plan.kept) await ctx.send(connectRequest(this.path, { ...c, from: rename(c.from), to: rename(c.to) }));
        } catch (e) {
            await this.putBack(ctx).catch(() => undefined);
            throw e;
        }
    }

    async undo(ctx: EditContext): Promise<void> {
        await this.putBack(ctx);
    }

    // the new component (if it was added) out, the old one in with every connection it had
    private async putBack(ctx: EditContext): Promise<void> {
        if (!this.old) return;
        if (this.actual) await ctx.send({ type: 'component.remove', system: this.path, name: this.actual });
        this.actual = '';
        await restoreComponent(ctx, this.path, this.old, this.old.name);
        for (const c of this.connections) await ctx.send(connectRequest(this.path, c));
    }
}
