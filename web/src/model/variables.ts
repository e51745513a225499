// Which logged result variable a port shows. The core logs every non-multiport port that sits
// on a node (Sub$Comp#Port#Var); multiports and lone inputs have no data of their own.
import { nodeVariables, type NodeVariable } from './nodeTypes';
import { sameRef, type SystemPath } from './modelState';
import type { Model, PortRef, System } from '../protocol/types';
import { systemAt } from './modelState';

export type PortVariables =
    /** `base` names the logged data; `label` the port that was asked about (the data may be logged under the port at the other end). */
    | { ok: true; base: string; label: string; nodeType: string; variables: NodeVariable[] }
    | { ok: false; reason: string };

function prefixOf(path: SystemPath): string {
    return path.map((name) => `${name}$`).join('');
}

/** The logged variables of a port of the system at `path`. */
export function portVariables(model: Model, path: SystemPath, ref: PortRef): PortVariables {
    const system = systemAt(model, path);
    if (!system) return { ok: false, reason: 'no such system' };
    // a system port seen from inside: logged as a port of the subsystem component outside
    const systemPort = system.ports.find((p) => p.name === ref.component && ref.port === ref.component);
    if (systemPort) {
        if (path.length === 0) return { ok: false, reason: 'ports of the root system are not logged' };
        const outer = path.slice(0, -1);
        const logged = portVariables(model, outer, { component: path[path.length - 1], port: ref.port });
        return logged.ok ? { ...logged, label: portLabel(path, ref) } : logged;
    }
    const component = system.components.find((c) => c.name === ref.component);
    const port = component?.ports.find((p) => p.name === ref.port);
    if (!component || !port) return { ok: false, reason: `no port ${ref.component}.${ref.port}` };
    const variables = nodeVariables[port.node_type] ?? [];
    if (port.multiport) {
        const other = otherEnd(system, ref);
        if (!other) return { ok: false, reason: `${ref.component}.${ref.port} is an unconnected multiport` };
        const logged = portVariables(model, path, other);
        return logged.ok ? { ...logged, label: portLabel(path, ref) } : logged;
    }
    if (port.kind === 'read' && !port.connected) {
        return { ok: false, reason: `${ref.component}.${ref.port} is an unconnected input (not logged)` };
    }
    if (variables.length === 0) return { ok: false, reason: `no variables for ${port.node_type}` };
    return { ok: true, base: `${prefixOf(path)}${component.name}#${port.name}`, label: portLabel(path, ref), nodeType: port.node_type, variables };
}

function portLabel(path: SystemPath, ref: PortRef): string {
    return `${prefixOf(path)}${ref.component}.${ref.port}`;
}

// The first non-multiport port connected to `ref`.
function otherEnd(system: System, ref: PortRef): PortRef | null {
    for (const c of system.connections) {
        const other = sameRef(c.from, ref) ? c.to : sameRef(c.to, ref) ? c.from : null;
        if (!other) continue;
        const comp = system.components.find((x) => x.name === other.component);
        const port = comp?.ports.find((p) => p.name === other.port);
        if (port && !port.multiport) return other;
    }
    return null;
}

/** What a plot sink (SignalSink, "Scope") of the root shows: the signals wired into it. */
export function sinkVariables(model: Model): string[] {
    const system = model.system;
    const names: string[] = [];
    for (const sink of system.components.filter((c) => c.type === 'SignalSink')) {
        for (const c of system.connections) {
            const other = c.to.component === sink.name ? c.from : c.from.component === sink.name ? c.to : null;
            if (!other) continue;
            const vars = portVariables(model, [], other);
            if (vars.ok) names.push(`${vars.base}#Value`);
        }
    }
    return [...new Set(names)];
}

/** "Comp#Port#Var" -> "Comp.Port Var" for legends. */
export function variableLabel(name: string): string {
    const [head, variable] = [name.slice(0, name.lastIndexOf('#')), name.slice(name.lastIndexOf('#') + 1)];
    return `${head.replace('#', '.')} ${variable}`;
}
