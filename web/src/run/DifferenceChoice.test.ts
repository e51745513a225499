// @vitest-environment jsdom
import { describe, expect, it, vi } from 'vitest';
import { DifferenceChoice } from './DifferenceChoice';

const runs = [7, 9, 12].map((jobId) => ({ jobId, label: `run ${jobId}` }));
const jobs = (pair: { a: { jobId: number }; b: { jobId: number } } | null) => pair && [pair.a.jobId, pair.b.jobId];

describe('DifferenceChoice', () => {
    it('is off until pressed, then subtracts the run before the shown one and follows the stepping', () => {
        const changed = vi.fn();
        const choice = new DifferenceChoice(changed);
        expect(choice.pair(runs, null)).toBeNull();
        expect(choice.bar.hidden).toBe(true);
        choice.button.click();
        expect(changed).toHaveBeenCalledTimes(1);
        expect(choice.button.getAttribute('aria-pressed')).toBe('true');
        expect(choice.bar.hidden).toBe(false);
        expect(jobs(choice.pair(runs, null))).toEqual([12, 9]);
        expect(jobs(choice.pair(runs, 9))).toEqual([9, 7]);
        expect(jobs(choice.pair(runs, 7))).toEqual([7, 9]);
        expect(choice.pair(runs.slice(0, 1), null)).toBeNull();
    });

    it('lists the runs in time order with the pair selected, and keeps the runs the user picks', () => {
        const choice = new DifferenceChoice(() => undefined);
        choice.button.click();
        choice.draw(runs, choice.pair(runs, null));
        const [a, b] = [...choice.bar.querySelectorAll('select')];
        expect([...a.options].map((o) => o.text)).toEqual(['run 7', 'run 9', 'run 12']);
        expect([a.value, b.value]).toEqual(['12', '9']);
        b.value = '7';
        b.dispatchEvent(new Event('change'));
        expect(jobs(choice.pair(runs, null))).toEqual([12, 7]);
        expect(jobs(choice.pair(runs, 9))).toEqual([9, 7]);   // A still follows the shown run
        // pressed again: off, and the picks are forgotten
        choice.button.click();
        expect(choice.pair(runs, null)).toBeNull();
        choice.button.click();
        expect(jobs(choice.pair(runs, null))).toEqual([12, 9]);
    });

    it('works from two runs on', () => {
        const choice = new DifferenceChoice(() => undefined);
        choice.draw(runs.slice(0, 1), null);
        expect(choice.button.disabled).toBe(true);
        choice.draw(runs, null);
        expect(choice.button.disabled).toBe(false);
    });
});
