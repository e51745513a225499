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

/** A plot window's zoom: the time shown, and the y ranges the user zoomed, keyed by the unit of the axis's values. */
export interface SavedZoom { x: [number, number]; y?: Record<string, [number, number]> }

/** A plot window: its variables, and its zoom when the user zoomed it. */
export interface SavedPlot { variables: SavedVariable[]; zoom?: SavedZoom }

/** The plot windows, in window order. */
export type SavedPlots = SavedPlot[];

export const plotsKey = (modelId: number) => `tlmhub.plots.${modelId}`;

/** Remembers the plot windows of a model; windows without variables are not kept. */
export function savePlots(storage: Storage, modelId: number, windows: SavedPlots): void {
    const kept = windows.filter((w) => w.variables.length > 0);
    try {
        if (kept.length === 0) storage.removeItem(plotsKey(modelId));
        else storage.setItem(plotsKey(modelId), JSON.stringify(kept));
    } catch {
        // storage full or forbidden: the plots are simply not remembered
    }
}

/**
 * The remembered plot windows of a model, keeping only variables `isKnown` accepts (the
 * model may have changed since) and dropping whatever is not in the saved form. A window saved
 * before zooms were kept is a list of its variables.
 */
export function loadPlots(storage: Storage, modelId: number, isKnown: (name: string) => boolean): SavedPlots {
    let saved: unknown;
    try {
        saved = JSON.parse(storage.getItem(plotsKey(modelId)) ?? '[]');
    } catch {
        return [];
    }
    if (!Array.isArray(saved)) return [];
    return saved.map((w: unknown): SavedPlot => {
        const { variables, zoom } = (Array.isArray(w) ? { variables: w } : typeof w === 'object' && w !== null ? w : {}) as { variables?: unknown; zoom?: unknown };
        const known = Array.isArray(variables) ? variables.filter((v): v is SavedVariable => isSavedVariable(v) && isKnown(v.name)) : [];
        return isSavedZoom(zoom) ? { variables: known, zoom } : { variables: known };
    }).filter((w) => w.variables.length > 0);
}

const isRange = (r: unknown): r is [number, number] =>
    Array.isArray(r) && r.length === 2 && r.every((v) => typeof v === 'number' && Number.isFinite(v)) && r[0] < r[1];

function isSavedZoom(z: unknown): z is SavedZoom {
    const x = z as Partial<SavedZoom> | null;
    if (typeof x !== 'object' || x === null || !isRange(x.x)) return false;
    return x.y === undefined || (typeof x.y === 'object' && x.y !== null && Object.values(x.y).every(isRange));
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
