import { describe, expect, it } from 'vitest';
import { spanText, stateText, whenText } from './historyRow';

// local times, as the panel shows them
const at = (...parts: [number, number, number, number, number]) => new Date(...parts).getTime() / 1000;

describe('whenText', () => {
    const now = new Date(2025, 5, 10, 14, 30);

    it('a recent run in minutes ago', () => {
        expect(whenText(at(2025, 5, 10, 14, 29) + 30, now)).toBe('just now');
        expect(whenText(at(2025, 5, 10, 14, 5), now)).toBe('25 min ago');
    });

    it('an earlier run of today at its time, of this year with its day, else its date', () => {
        expect(whenText(at(2025, 5, 10, 9, 7), now)).toBe('09:07');
        expect(whenText(at(2025, 2, 12, 16, 45), now)).toBe('12 Mar 16:45');
        expect(whenText(at(2024, 11, 31, 23, 0), now)).toBe('2024-12-31');
    });
});

describe('stateText', () => {
    it('names what became of the run, with the reason a model or a failure gave', () => {
        expect(stateText({ state: 'done', error: '' })).toBe('done');
        expect(stateText({ state: 'done', error: '', stop_reason: 'Simulation stopped by Stop' })).toBe('ended by model: Simulation stopped by Stop');
        expect(stateText({ state: 'failed', error: 'division by zero in Gain' })).toBe('failed: division by zero in Gain');
        expect(stateText({ state: 'failed', error: '' })).toBe('failed');
        expect(stateText({ state: 'cancelled', error: '' })).toBe('cancelled');
        expect(stateText({ state: 'running', error: '' })).toBe('running');
    });
});

describe('spanText', () => {
    it('the simulated time and, once known, the steps', () => {
        expect(spanText({ settings: { start: 0, step: 0.001, stop: 3, log_samples: 0 }, steps: 3000 })).toBe('0–3 s, 3000 steps');
        expect(spanText({ settings: { start: 1, step: 0.001, stop: 2, log_samples: 0 }, steps: 0 })).toBe('1–2 s');
    });
});
