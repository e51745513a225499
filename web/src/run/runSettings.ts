// Checks the run bar's fields before a run: one message per wrong field, in words, so it can
// be shown next to that field (the server's schema errors name paths, not fields a user sees).
import type { RunSettings } from './RunController';
import type { SimulationSettings } from '../protocol/types';

export type RunField = keyof RunSettings;
export const RUN_FIELDS: readonly RunField[] = ['start', 'step', 'stop', 'log_samples'];
export const FIELD_LABELS: Record<RunField, string> = { start: 'Start time', step: 'Time step', stop: 'Stop time', log_samples: 'Log samples' };

export interface CheckedRunSettings {
    /** The fields typed in; empty ones are left out (the model's own apply). */
    values: Partial<RunSettings>;
    errors: Partial<Record<RunField, string>>;
}

/** `typed` holds each field's text; `model` the model's own settings that empty fields fall back to. */
export function checkRunSettings(typed: Record<RunField, string>, model: SimulationSettings | undefined): CheckedRunSettings {
    const values: Partial<RunSettings> = {};
    const errors: Partial<Record<RunField, string>> = {};
    for (const field of RUN_FIELDS) {
        const text = typed[field].trim();
        if (text === '') continue;
        const value = Number(text);
        if (!Number.isFinite(value)) errors[field] = `${FIELD_LABELS[field]} must be a number.`;
        else values[field] = value;
    }
    const effective = (field: RunField): number | undefined => values[field] ?? model?.[field];
    const step = effective('step');
    if (!errors.step && step !== undefined && !(step > 0)) errors.step = 'Time step must be greater than 0.';
    const start = effective('start');
    const stop = effective('stop');
    if (!errors.stop && !errors.start && start !== undefined && stop !== undefined && !(stop > start)) {
        errors.stop = `Stop time must be after the start time (${start} s).`;
    }
    const samples = values.log_samples;
    if (!errors.log_samples && samples !== undefined && !(Number.isInteger(samples) && samples >= 1)) {
        errors.log_samples = 'Log samples must be a whole number of at least 1.';
    }
    return { values, errors };
}

/**
 * A server refusal of one of the fields ("message.log_samples: must be >= 1, got 0") as that
 * field and a sentence; null for other errors.
 */
export function fieldOfServerError(message: string): { field: RunField; text: string } | null {
    const m = /^message\.(start|step|stop|log_samples): (.*)$/.exec(message.trim());
    if (!m) return null;
    const field = m[1] as RunField;
    const reason = m[2].replace(/>=\s*/g, 'at least ').replace(/<=\s*/g, 'at most ').replace(/, got .*$/, '');
    return { field, text: `${FIELD_LABELS[field]} ${reason}.` };
}
