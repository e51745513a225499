// @vitest-environment jsdom
// The model list searched and sorted: the search box keeps the models whose name or owner
// holds every word, in each section; a header click sorts that section.
import { describe, expect, it } from 'vitest';
import { renderModelList } from './ModelListView';
import type { Session } from '../app/Session';
import type { ModelSummary } from '../protocol/types';

const model = (id: number, name: string, owner: string, updated: number, example = false): ModelSummary =>
    ({ id, name, owner: { id: owner === 'alice' ? 1 : 2, username: owner }, is_example: example, created_at: 0, updated_at: updated });
const models = [
    model(1, 'Servo tuning', 'alice', 300), model(2, 'Pump test', 'alice', 100), model(3, 'Servo 2', 'alice', 200),
    model(4, 'Position Servo', 'admin', 50, true), model(5, 'Pump', 'admin', 60, true),
];
const session = { rest: { listModels: async () => models }, user: { id: 1, username: 'alice', role: 'user' } } as unknown as Session;
const names = (section: string) => [...document.querySelectorAll(`[data-testid="${section}"] tbody tr`)].map((r) => r.querySelector('a')?.textContent);

describe('model list', () => {
    it('searches by name or owner in every section, and sorts a section by a header click', async () => {
        document.body.replaceChildren();
        await renderModelList(document.body, session, () => undefined);
        expect(names('own-models')).toEqual(['Pump test', 'Servo 2', 'Servo tuning']);
        expect(names('example-models')).toEqual(['Position Servo', 'Pump']);

        const search = document.querySelector<HTMLInputElement>('input[name="model-search"]')!;
        search.value = 'servo';
        search.dispatchEvent(new Event('input'));
        expect(names('own-models')).toEqual(['Servo 2', 'Servo tuning']);
        expect(names('example-models')).toEqual(['Position Servo']);
        search.value = 'pump admin';
        search.dispatchEvent(new Event('input'));
        expect(names('own-models')).toEqual([]);
        expect(document.querySelector('[data-testid="own-models"]')!.textContent).toContain('No model matches the search.');
        expect(names('example-models')).toEqual(['Pump']);

        search.value = '';
        search.dispatchEvent(new Event('input'));
        document.querySelector<HTMLButtonElement>('[data-testid="own-models"] th[data-column="changed"] button')!.click();
        expect(names('own-models')).toEqual(['Servo tuning', 'Servo 2', 'Pump test']);   // newest first
        search.value = 's';
        search.dispatchEvent(new Event('input'));   // the order stays while searching
        expect(names('own-models')).toEqual(['Servo tuning', 'Servo 2', 'Pump test']);
    });
});
