// What a Bode window compares by default, as in Hopsan: the model's signal source (the step or
// sine that drives it) is the input and the variable the user plotted the output.
import type { Model, System } from '../protocol/types';
import type { SystemPath } from '../model/modelState';
import { portVariables } from '../model/variables';

/**
 * The logged outputs of the model's signal sources (root system first, then subsystems): Signal*
 * components that write a signal and read none over a connection. Their unconnected read
 * ports are parameters given as inputs (a step's y_0, y_A, t_step). A constant is left out: it
 * excites no frequency.
 */
export function signalSources(model: Model): string[] {
    const found: string[] = [];
    const visit = (system: System, path: SystemPath) => {
        for (const c of system.components) {
            if (!c.type.startsWith('Signal') || c.type === 'SignalConstant') continue;
            if (c.ports.some((p) => (p.kind === 'read' || p.kind === 'bidirectional') && p.connected)) continue;
            for (const p of c.ports.filter((x) => x.kind === 'write')) {
                const logged = portVariables(model, path, { component: c.name, port: p.name });
                if (logged.ok) found.push(`${logged.base}#Value`);
            }
        }
        for (const c of system.components) if (c.system) visit(c.system, [...path, c.name]);
    };
    visit(model.system, []);
    return found;
}

/**
 * The input is a source (a plotted one first), else the first plotted variable; the output is
 * the first plotted variable that is not the input.
 */
export function bodePair(plotted: string[], sources: string[]): { input?: string; output?: string } {
    const input = sources.find((s) => plotted.includes(s)) ?? sources[0] ?? plotted[0];
    return { input, output: plotted.find((v) => v !== input) ?? input };
}
