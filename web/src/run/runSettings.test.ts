import { describe, expect, it } from 'vitest';
import { checkRunSettings, fieldOfServerError } from './runSettings';

const model = { start: 0, step: 1e-3, stop: 10, log_samples: 2048 };
const typed = (t: Partial<Record<'start' | 'step' | 'stop' | 'log_samples', string>>) => ({ start: '', step: '', stop: '', log_samples: '', ...t });

describe('checkRunSettings', () => {
    it('accepts the defaults and leaves empty fields to the model', () => {
        expect(checkRunSettings(typed({}), model)).toEqual({ values: {}, errors: {} });
        expect(checkRunSettings(typed({ stop: '2.5', log_samples: '100' }), model)).toEqual({ values: { stop: 2.5, log_samples: 100 }, errors: {} });
    });

    it('gives one sentence per wrong field', () => {
        const { errors } = checkRunSettings(typed({ start: 'abc', step: '0', log_samples: '0' }), model);
        expect(errors).toEqual({
            start: 'Start time must be a number.',
            step: 'Time step must be greater than 0.',
            log_samples: 'Log samples must be a whole number of at least 1.',
        });
    });

    it('checks the stop time against the effective start time', () => {
        expect(checkRunSettings(typed({ start: '5', stop: '5' }), model).errors).toEqual({ stop: 'Stop time must be after the start time (5 s).' });
        expect(checkRunSettings(typed({ start: '20' }), model).errors).toEqual({ stop: 'Stop time must be after the start time (20 s).' });
        expect(checkRunSettings(typed({ log_samples: '2.5' }), model).errors.log_samples).toMatch(/whole number/);
    });
});

describe('fieldOfServerError', () => {
    it('turns a schema path into the field and words', () => {
        expect(fieldOfServerError('message.log_samples: must be >= 1, got 0')).toEqual({ field: 'log_samples', text: 'Log samples must be at least 1.' });
        expect(fieldOfServerError('the model does not load')).toBeNull();
    });
});
