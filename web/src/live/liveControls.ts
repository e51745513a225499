// Live controls placed on the drawing (a slider, knob, switch or number field bound to a value
// that may change while the model runs) are part of the model: a teacher puts them in an
// assignment's template, and they must survive save, reopen, "save as my copy" and .hmf.
// The server keeps them in the model's GUI data (the root's `live_controls`, model.controls;
// <hopsangui><tlmhub_livecontrols> in the .hmf). Models saved before that kept them as a
// JSON string system parameter, which is still read until the controls are next changed.
import type { LiveControl as StoredControl, Model, SysParam } from '../protocol/types';
import { findComponent, systemAt, type SystemPath } from '../model/modelState';

export type LiveControlKind = StoredControl['kind'];
export const CONTROL_KINDS: readonly LiveControlKind[] = ['slider', 'knob', 'switch', 'number'];

/** A control as the editor handles it: as stored, its drawing's subsystem path always given. */
export type LiveControl = Omit<StoredControl, 'system'> & {
    /** The drawing it is on; x and y are in its coordinates. */
    path: SystemPath;
};

/** The system parameter that held them in models saved before they had their own place (top-level system). */
export const CONTROLS_PARAMETER = 'tlmhub_live_controls';

/** The model's live controls; those that do not make sense (edited by hand) are left out. */
export function controlsOf(model: Model): LiveControl[] {
    const stored = model.system.live_controls;
    if (stored?.length) return stored.flatMap((c) => {
        const control = checked({ ...c, path: c.system ?? [] });
        return control ? [control] : [];
    });
    return legacyControlsOf(model);
}

/** The controls the model's old system parameter holds, if it has it (and not yet controls of its own). */
export function legacyControlParameter(model: Model): SysParam | undefined {
    return model.system.live_controls?.length ? undefined : model.system.parameters.find((p) => p.name === CONTROLS_PARAMETER);
}

function legacyControlsOf(model: Model): LiveControl[] {
    const text = legacyControlParameter(model)?.value;
    if (!text) return [];
    let parsed: unknown;
    try {
        parsed = JSON.parse(text);
    } catch {
        return [];
    }
    return Array.isArray(parsed) ? parsed.flatMap((c) => {
        const control = checked(c);
        return control ? [control] : [];
    }) : [];
}

/** `controls` as model.controls stores them: on whole pixels, a switch with both of its values. */
export function storedControls(controls: readonly LiveControl[]): StoredControl[] {
    return controls.map((c) => {
        const stored: StoredControl = { kind: c.kind, name: c.name, min: c.min, max: c.max, x: Math.round(c.x), y: Math.round(c.y) };
        if (c.kind === 'switch') {
            stored.off = c.off ?? c.min;
            stored.on = c.on ?? c.max;
        }
        if (c.path.length) stored.system = [...c.path];
        return stored;
    });
}

/**
 * The value a live value has in the model (`Step.y_A` is Step's input y_A, stored as
 * `y_A#Value`; `Sub$Gain.k` is inside Sub), when it is a plain number: what a control shows
 * before a session runs.
 */
export function modelValueOf(model: Model, name: string): number | undefined {
    const dot = name.lastIndexOf('.');
    if (dot < 0) return undefined;
    const path = name.slice(0, dot).split('$');
    const component = path.pop()!;
    const system = systemAt(model, path);
    const parameters = system ? findComponent(system, component)?.parameters ?? [] : [];
    const parameter = name.slice(dot + 1);
    const text = parameters.find((p) => p.name === parameter || p.name === `${parameter}#Value`)?.value;
    const value = text === undefined || text.trim() === '' ? Number.NaN : Number(text);
    return Number.isFinite(value) ? value : undefined;
}

/** A switch's off and on values; the other kinds' ends. */
export function controlRange(c: LiveControl): { low: number; high: number } {
    return c.kind === 'switch' ? { low: c.off ?? c.min, high: c.on ?? c.max } : { low: c.min, high: c.max };
}

/** Bounds a live value must keep (an assignment's locked copy: live_values' min and max). */
export interface LiveBounds { min?: number; max?: number }

/**
 * The control as `bounds` allow it: its range cut to them (a switch's values too), or the
 * bounds themselves when its range lies outside them; so it never sends a value the server
 * would refuse (locked).
 */
export function withinBounds(c: LiveControl, bounds: LiveBounds | undefined): LiveControl {
    if (!bounds || (bounds.min === undefined && bounds.max === undefined)) return c;
    const clamp = (v: number) => Math.min(bounds.max ?? Infinity, Math.max(bounds.min ?? -Infinity, v));
    let [min, max] = [clamp(c.min), clamp(c.max)];
    if (min >= max && bounds.min !== undefined && bounds.max !== undefined && bounds.min < bounds.max) [min, max] = [bounds.min, bounds.max];
    const bounded: LiveControl = { ...c, min, max };
    if (c.kind === 'switch') {
        bounded.off = clamp(c.off ?? c.min);
        bounded.on = clamp(c.on ?? c.max);
    }
    return bounded;
}

/** Why a control's numbers cannot be used, or '' (min below max; a switch's two values differ). */
export function controlProblem(c: Pick<LiveControl, 'kind' | 'min' | 'max' | 'off' | 'on'>): string {
    const numbers = [c.min, c.max, ...(c.kind === 'switch' ? [c.off, c.on] : [])];
    if (!numbers.every((n) => typeof n === 'number' && Number.isFinite(n))) return 'Every value must be a number.';
    if (c.kind === 'switch') return c.off === c.on ? 'Off and on must differ.' : '';
    return c.min < c.max ? '' : 'Min must be below max.';
}

function checked(raw: unknown): LiveControl | null {
    if (typeof raw !== 'object' || raw === null) return null;
    const c = raw as Record<string, unknown>;
    const number = (v: unknown) => (typeof v === 'number' && Number.isFinite(v) ? v : undefined);
    const kind = CONTROL_KINDS.find((k) => k === c.kind);
    const [min, max, x, y] = [number(c.min), number(c.max), number(c.x), number(c.y)];
    if (!kind || typeof c.name !== 'string' || c.name === '' || min === undefined || max === undefined || x === undefined || y === undefined) return null;
    const path = Array.isArray(c.path) && c.path.every((p) => typeof p === 'string') ? c.path as string[] : [];
    const control: LiveControl = { kind, name: c.name, min, max, x, y, path };
    if (kind === 'switch') {
        control.off = number(c.off) ?? min;
        control.on = number(c.on) ?? max;
    }
    return control;
}
