// The model's parameters a study can vary, named as the server names them (docs/studies.md):
// `Comp.param` ("#Value" left out, as Hopsan's expressions write it), `Sub$Comp.param`
// inside subsystem Sub, a system parameter of the top level by its name.
import type { Model, System } from '../protocol/types';
import type { SystemPath } from '../model/modelState';

export interface StudyParameter {
    /** The name a study request uses. */
    name: string;
    /** Where the value lives: a component's parameter, or a system parameter (component null). */
    path: SystemPath;
    component: string | null;
    parameter: string;
    unit: string;
    description: string;
    /** The value text in the model (a number, an expression or a system parameter's name). */
    text: string;
    /** The value as a number; null when the text is not a plain number. */
    value: number | null;
}

const NUMERIC_TYPES = new Set(['double', 'integer']);

function numberOf(text: string): number | null {
    if (text.trim() === '') return null;
    const n = Number(text);
    return Number.isFinite(n) ? n : null;
}

/** The number-valued parameters: system parameters first, then the components' in model order. */
export function studyParameters(model: Model): StudyParameter[] {
    const found: StudyParameter[] = model.system.parameters
        .filter((p) => NUMERIC_TYPES.has(p.type))
        .map((p) => ({ name: p.name, path: [], component: null, parameter: p.name, unit: p.unit, description: p.description, text: p.value, value: numberOf(p.value) }));
    const collect = (system: System, path: SystemPath) => {
        for (const c of system.components) {
            if (c.system) {
                collect(c.system, [...path, c.name]);
                continue;
            }
            for (const p of c.parameters) {
                // a node's start values (P1#Pressure) are left out: a study varies the component's own parameters
                const hash = p.name.indexOf('#');
                if (!NUMERIC_TYPES.has(p.type) || (hash >= 0 && !p.name.endsWith('#Value'))) continue;
                const short = p.name.replace(/#Value$/, '');
                found.push({
                    name: `${path.map((s) => `${s}$`).join('')}${c.name}.${short}`, path, component: c.name, parameter: p.name,
                    unit: p.unit, description: p.description, text: p.value, value: numberOf(p.value),
                });
            }
        }
    };
    collect(model.system, []);
    return found;
}

/** The parameter a study name (as in a study's table or best point) refers to, if the model has it. */
export function parameterNamed(model: Model, name: string): StudyParameter | undefined {
    const all = studyParameters(model);
    return all.find((p) => p.name === name) ?? all.find((p) => `${p.name}#Value` === name || p.name === name.replace(/#Value$/, ''));
}
