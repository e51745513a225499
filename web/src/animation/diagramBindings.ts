// Which logged variables drive the drawing of one system: per hydraulic line the node's
// pressure and the flow through it, per animated component the variables of its movable parts
// and the parameters that divide them. Names are those of the results (Sub$Comp#Port#Var).
import { portVariables } from '../model/variables';
import { systemAt, type SystemPath } from '../model/modelState';
import { animationOf, type AnimationDescription } from './descriptions';
import type { Connection, Model, PortRef } from '../protocol/types';

export interface LineBinding {
    connection: Connection;
    /** The node's pressure (the `Pressure` of either end: one node, one pressure). */
    pressure: string;
    /**
     * The flow into the component at one end (`Flow` of a port that is not a multiport), and
     * `sign`: +1 when a positive flow runs along the line from `from` to `to`, −1 against it.
     */
    flow: string | null;
    sign: 1 | -1;
}

export interface ComponentBinding {
    name: string;
    type: string;
    description: AnimationDescription;
    /** Per movable, per data entry: the variable's name, or null when the port logs nothing (at rest). */
    data: (string | null)[][];
    /** The component's parameter values that are plain numbers, by name (`s_l#Value`). */
    parameters: Map<string, number>;
}

export interface DiagramBindings { lines: LineBinding[]; components: ComponentBinding[] }

export function diagramBindings(model: Model, path: SystemPath): DiagramBindings {
    const system = systemAt(model, path);
    if (!system) return { lines: [], components: [] };
    const hydraulic = (ref: PortRef) => {
        const v = portVariables(model, path, ref);
        return v.ok && v.nodeType === 'NodeHydraulic' ? v : null;
    };
    const isMultiport = (ref: PortRef) =>
        system.components.find((c) => c.name === ref.component)?.ports.find((p) => p.name === ref.port)?.multiport ?? false;
    const lines: LineBinding[] = [];
    for (const connection of system.connections) {
        const from = hydraulic(connection.from);
        const to = hydraulic(connection.to);
        const any = from ?? to;
        if (!any) continue;
        // a multiport's variables are another line's port: its flow is not this line's
        // (Hopsan's sign: a positive flow goes into the component at the port)
        const flow = from && !isMultiport(connection.from) ? { name: `${from.base}#Flow`, sign: -1 as const }
            : to && !isMultiport(connection.to) ? { name: `${to.base}#Flow`, sign: 1 as const } : null;
        lines.push({ connection, pressure: `${any.base}#Pressure`, flow: flow?.name ?? null, sign: flow?.sign ?? 1 });
    }
    const systemNumbers = new Map(system.parameters.map((p) => [p.name, Number(p.value)]));
    const components: ComponentBinding[] = [];
    for (const c of system.components) {
        const description = animationOf(c.type);
        if (!description) continue;
        const data = description.movables.map((m) => m.data.map(([port, variable]) => {
            const v = portVariables(model, path, { component: c.name, port });
            return v.ok && v.variables.some((x) => x.name === variable) ? `${v.base}#${variable}` : null;
        }));
        const parameters = new Map<string, number>();
        for (const p of c.parameters) {
            // a parameter may name a system parameter (Hopsan's expressions are not evaluated here)
            const n = p.value.trim() === '' ? NaN : Number(p.value);
            const value = Number.isFinite(n) ? n : systemNumbers.get(p.value.trim());
            if (value !== undefined && Number.isFinite(value)) parameters.set(p.name, value);
        }
        components.push({ name: c.name, type: c.type, description, data, parameters });
    }
    return { lines, components };
}

/** A divisor as the descriptions name it (`s_l#Value`, or a bare `max`) in a component's parameters. */
export function parameterValue(parameters: Map<string, number>, name: string): number | undefined {
    return parameters.get(name) ?? parameters.get(`${name}#Value`);
}

/** Every variable the bindings read, without repeats. */
export function boundVariables(b: DiagramBindings): string[] {
    const names = new Set<string>();
    for (const l of b.lines) {
        names.add(l.pressure);
        if (l.flow) names.add(l.flow);
    }
    for (const c of b.components) for (const m of c.data) for (const n of m) if (n) names.add(n);
    return [...names];
}
