// What a run of the model's history used that the latest run did not: the hover text of a
// history row. The server lists, per run, the values it used that the model's text now says
// otherwise (differing_parameters); any other parameter the run used as the model says now.
import type { JobInfo, Model, System } from '../protocol/types';

/** A parameter whose value two runs differ in; null where the run had no such parameter. */
export interface ParameterDifference { path: string; value: string | null; latest: string | null }

/**
 * Every parameter value text of a model by the server's path: a system parameter by its name,
 * 'Comp.param' ('Comp.P#Value' for a start value), 'Sub$Comp.param' inside subsystem Sub.
 */
export function parameterTexts(model: Model): Map<string, string> {
    const texts = new Map<string, string>();
    for (const p of model.system.parameters) texts.set(p.name, p.value);
    const collect = (system: System, prefix: string) => {
        for (const c of system.components) {
            const owner = prefix + c.name;
            for (const p of c.parameters) texts.set(`${owner}.${p.name}`, p.value);
            if (c.system) collect(c.system, `${owner}$`);
        }
    };
    collect(model.system, '');
    return texts;
}

/**
 * The parameters `run` used a value of other than `latest` did, by path, and whether there
 * may be more (the server cut either run's list short). `now` is the model's value text.
 */
export function differencesFromLatest(run: JobInfo, latest: JobInfo, now: (path: string) => string | undefined):
    { differences: ParameterDifference[]; more: boolean } {
    if (run.id === latest.id) return { differences: [], more: false };
    const ran = run.differing_parameters ?? {};
    const last = latest.differing_parameters ?? {};
    const used = (differing: Record<string, string>, path: string) => differing[path] ?? now(path) ?? null;
    const paths = [...new Set([...Object.keys(ran), ...Object.keys(last)])].sort();
    const differences = paths.map((path) => ({ path, value: used(ran, path), latest: used(last, path) }))
        .filter((d) => d.value !== d.latest);
    return { differences, more: Boolean(run.differing_parameters_truncated || latest.differing_parameters_truncated) };
}

/** How a path reads to a Hopsan user: a start value without "#Value", as typed in expressions. */
export const parameterLabel = (path: string) => path.replace(/#Value$/, '');

/**
 * The hover text of a run: one line per difference, "GainP.k: 0.02 (latest 0.0264249)", at
 * most `maxLines` of them, then how many more.
 */
export function differencesText(found: { differences: ParameterDifference[]; more: boolean }, maxLines = 12): string {
    const { differences, more } = found;
    if (differences.length === 0) return more ? 'No listed parameter differs from the latest run (the server cut the list short)' : 'Same parameters as the latest run';
    const shown = differences.slice(0, maxLines).map((d) => `${parameterLabel(d.path)}: ${d.value ?? 'none'} (latest ${d.latest ?? 'none'})`);
    const hidden = differences.length - shown.length;
    const tail = hidden > 0 ? [`and ${hidden}${more ? '+' : ''} more`] : more ? ['and more'] : [];
    return ['Differs from the latest run in:', ...shown, ...tail].join('\n');
}
