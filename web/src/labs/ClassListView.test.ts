// @vitest-environment jsdom
// The class list searched and sorted: the search keeps the classes whose name, teacher or the
// caller's role holds every word; a header click sorts by that column.
import { describe, expect, it } from 'vitest';
import { renderClassList } from './ClassListView';
import type { Session } from '../app/Session';
import type { LabClass } from './types';

const lab = (id: number, name: string, teacher: string, created: number): LabClass =>
    ({ id, name, owner: { id: id + 10, username: teacher }, archived: false, created_at: created, role: 'student' });
const classes = [lab(1, 'Fluid power 2026', 'tina', 300), lab(2, 'Control 2', 'tom', 100), lab(3, 'Control 10', 'tina', 200)];
const session = { labs: { listClasses: async () => classes }, user: { id: 1, username: 'stan', role: 'user' } } as unknown as Session;
const shown = () => [...document.querySelectorAll('[data-testid="class-list"] tbody tr')].map((r) => r.querySelector('a')?.textContent ?? r.textContent);

describe('class list', () => {
    it('searches by class or teacher and sorts by a header click', async () => {
        document.body.replaceChildren();
        await renderClassList(document.body, session);
        expect(shown()).toEqual(['Control 2', 'Control 10', 'Fluid power 2026']);

        const search = document.querySelector<HTMLInputElement>('input[name="class-search"]')!;
        search.value = 'TINA';
        search.dispatchEvent(new Event('input'));
        expect(shown()).toEqual(['Control 10', 'Fluid power 2026']);
        search.value = 'control tina';
        search.dispatchEvent(new Event('input'));
        expect(shown()).toEqual(['Control 10']);
        search.value = 'acoustics';
        search.dispatchEvent(new Event('input'));
        expect(shown()).toEqual(['No class matches the search.']);

        search.value = '';
        search.dispatchEvent(new Event('input'));
        document.querySelector<HTMLButtonElement>('th[data-column="created"] button')!.click();
        expect(shown()).toEqual(['Fluid power 2026', 'Control 10', 'Control 2']);   // newest first
    });
});
