// The model's logged result variables by name (Comp#Port#Var, Sub$Comp#Port#Var): what a
// study's outputs and objective terms may read.
import { portVariables } from '../model/variables';
import { primaryVariables } from '../model/nodeTypes';
import type { SystemPath } from '../model/modelState';
import type { Model, System } from '../protocol/types';

export interface LoggedVariable { name: string; unit: string }

/** Every logged variable once, intensities and flows (Position, Pressure, Value …) first. */
export function loggedVariables(model: Model): LoggedVariable[] {
    const seen = new Map<string, LoggedVariable>();
    const walk = (system: System, path: SystemPath) => {
        for (const c of system.components) {
            if (c.system) walk(c.system, [...path, c.name]);
            for (const port of c.ports) {
                const vars = portVariables(model, path, { component: c.name, port: port.name });
                if (!vars.ok) continue;
                for (const v of vars.variables) {
                    const name = `${vars.base}#${v.name}`;
                    if (!seen.has(name)) seen.set(name, { name, unit: v.unit });
                }
            }
        }
    };
    walk(model.system, []);
    const primary = (v: LoggedVariable) => primaryVariables.has(v.name.slice(v.name.lastIndexOf('#') + 1));
    return [...seen.values()].sort((a, b) => Number(primary(b)) - Number(primary(a)));
}
