// What the editor shows again when a model is opened (after a reload, say): the model's last
// finished runs from the server's run history, and the plot windows the user had, kept in
// localStorage per model.
import type { JobInfo, Model } from '../protocol/types';
import { portVariables } from '../model/variables';

/** How many of the newest runs are looked through for ones to show again. */
export const HISTORY_PAGE = 20;

/**
 * The runs of a history that ended well and whose results the server still has, newest first:
 * the one to show, the one to compare with, and earlier ones to step back to. Failed, stopped
 * or still running jobs are skipped, as are runs whose results were dropped (they could draw
 * nothing).
 */
export function restorableRuns(history: JobInfo[]): JobInfo[] {
    return history.filter((job) => job.state === 'done' && !job.results_dropped)
        .sort((a, b) => b.id - a.id);   // newest first, whatever order the page came in
}

/** A plotted variable as its window shows it: the name of its curve and its axis's unit. */
export interface SavedVariable { name: string; label: string; unit: string }

/** The variables of each plot window, in window order. */
export type SavedPlots = SavedVariable[][];

export const plotsKey = (modelId: number) => `tlmhub.plots.${modelId}`;

/** Remembers the plot windows of a model; windows without variables are not kept. */
export function savePlots(storage: Storage, modelId: number, windows: SavedPlots): void {
    const kept = windows.filter((w) => w.length > 0);
    try {
        if (kept.length === 0) storage.removeItem(plotsKey(modelId));
        else storage.setItem(plotsKey(modelId), JSON.stringify(kept));
    } catch {
        // storage full or forbidden: the plots are simply not remembered
    }
}

/**
 * The remembered plot windows of a model, keeping only variables `isKnown` accepts (the
 * model may have changed since) and dropping whatever is not in the saved form.
 */
export function loadPlots(storage: Storage, modelId: number, isKnown: (name: string) => boolean): SavedPlots {
    let saved: unknown;
    try {
        saved = JSON.parse(storage.getItem(plotsKey(modelId)) ?? '[]');
    } catch {
        return [];
    }
    if (!Array.isArray(saved)) return [];
    return saved
        .map((w: unknown) => (Array.isArray(w) ? w.filter((v): v is SavedVariable => isSavedVariable(v) && isKnown(v.name)) : []))
        .filter((w) => w.length > 0);
}

function isSavedVariable(v: unknown): v is SavedVariable {
    const x = v as Partial<SavedVariable> | null;
    return typeof x === 'object' && x !== null && typeof x.name === 'string' && typeof x.label === 'string' && typeof x.unit === 'string';
}

/** Whether `name` (Sub$Comp#Port#Var) is a variable the model logs. */
export function isLoggedVariable(model: Model, name: string): boolean {
    const [qualified, port, variable, ...rest] = name.split('#');
    if (port === undefined || variable === undefined || rest.length > 0) return false;
    const path = qualified.split('$');
    const component = path.pop()!;
    const logged = portVariables(model, path, { component, port });
    return logged.ok && logged.base === `${qualified}#${port}` && logged.variables.some((v) => v.name === variable);
}
