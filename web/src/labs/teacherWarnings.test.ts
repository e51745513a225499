// @vitest-environment jsdom
// The teacher is warned in words, and curve checks say which rule their tolerance follows:
// new ones relative to the reference's largest magnitude, older ones as they were stored.
import { describe, expect, it, vi } from 'vitest';
import { assignmentWarnings, warningText, type TeacherAssignment } from './AssignmentWarnings';
import { checksEditor, curveScaleOf, readDefinition } from './ChecksEditor';
import type { Check } from './types';

const assignment = (warnings?: TeacherAssignment['warnings']): TeacherAssignment => ({
    id: 1, class_id: 1, title: 'Tune the servo', instructions: '', edit_mode: 'parameters',
    parameters: [{ name: 'GainP.k', min: 0, max: 0.01 }], opens_at: 0, due_at: 0, template_version: 1,
    has_solution: true, created_at: 0, updated_at: 0, warnings,
});

const outside = { code: 'template_outside_bounds', message: 'The template sets GainP.k to 0.0264249, outside the bounds you set (between 0 and 0.01).' } as const;

describe('the teacher\'s warnings', () => {
    it('shows nothing without warnings', () => {
        expect(assignmentWarnings(assignment())).toBeNull();
        expect(assignmentWarnings(assignment([]))).toBeNull();
    });
    it('lists each warning in words, with what to do about it', () => {
        const panel = assignmentWarnings(assignment([outside,
            { code: 'solution_fails_check', message: 'The solution fails the check "Ends high": the final of x is 0.5, required at least 1.' }]));
        expect(panel?.textContent).toContain('Check these 2 things before students start');
        const items = [...panel!.querySelectorAll('li')];
        expect(items.map((li) => li.dataset.code)).toEqual(['template_outside_bounds', 'solution_fails_check']);
        expect(items[0].textContent).toBe(warningText(outside));
        expect(items[0].textContent).toMatch(/^The template sets GainP\.k to 0\.0264249, outside .* Students start outside the bounds/);
        expect(items[1].textContent).toContain('loosen the check or correct the solution');
    });
});

describe('the rule of a curve check\'s tolerance', () => {
    const fields = { kind: 'curve', variable: 'x', tolerance: '0.02', measure: 'final', min: '', max: '', band: '' };
    it('sends scale range only when chosen, so older checks stay as stored', () => {
        expect(readDefinition({ ...fields, scale: 'range' }, 'c')).toEqual({ kind: 'curve', variable: 'x', tolerance: 0.02, scale: 'range' });
        expect(readDefinition({ ...fields, scale: 'sample' }, 'c')).toEqual({ kind: 'curve', variable: 'x', tolerance: 0.02 });
    });
    it('is range for new checks and the stored one for existing checks', () => {
        expect(curveScaleOf(undefined)).toBe('range');
        expect(curveScaleOf({ kind: 'curve', variable: 'x' })).toBe('sample');
        expect(curveScaleOf({ kind: 'curve', variable: 'x', scale: 'range' } as Check['definition'])).toBe('range');
    });
    it('defaults a check added in the editor to range and keeps an old one\'s rule when saved', async () => {
        const old: Check = { name: 'Old', points: 1, pretest: false, definition: { kind: 'curve', variable: 'x', tolerance: 0.05 } };
        const save = vi.fn(async (_checks: Check[]) => undefined);
        const form = checksEditor({ checks: [old], editable: true, hasSolution: true, save });
        document.body.append(form);
        const rules = () => [...form.querySelectorAll<HTMLSelectElement>('select[aria-label="Relative to"]')];
        expect(rules()[0].value).toBe('sample');
        expect(rules()[0].selectedOptions[0].textContent).toBe('each reference sample (.hvc rule)');
        form.querySelector<HTMLButtonElement>('[data-testid="add-check"]')!.click();
        expect(rules()[1].value).toBe('range');
        const rows = form.querySelectorAll('fieldset.check-row');
        rows[1].querySelector<HTMLInputElement>('input[aria-label="Check name"]')!.value = 'New';
        rows[1].querySelector<HTMLInputElement>('input[aria-label="Variable"]')!.value = 'y';
        form.querySelector<HTMLButtonElement>('button[type="submit"]')!.click();
        await vi.waitFor(() => expect(save).toHaveBeenCalled());
        const saved = save.mock.calls[0][0];
        expect(saved[0].definition).toEqual({ kind: 'curve', variable: 'x', tolerance: 0.05 });
        expect(saved[1].definition).toEqual({ kind: 'curve', variable: 'y', scale: 'range' });
        form.remove();
    });
});
