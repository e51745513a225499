// @vitest-environment jsdom
// Sorting by a column (empty cells last both ways, names as people read them, ties kept in
// order), the list search (every word, any case), and the table's header clicks; the
// gradebook table built on it.
import { describe, expect, it } from 'vitest';
import { filterRows, nextOrder, sortableTable, sortRows, type Column } from './sortableTable';
import { gradebookRows, gradebookTable } from '../labs/GradebookTable';
import type { Gradebook } from '../labs/types';

interface Item { name: string; score: number | null }
const columns: Column<Item>[] = [
    { key: 'name', label: 'Name', value: (r) => r.name },
    { key: 'score', label: 'Score', value: (r) => r.score, numeric: true },
];
const items: Item[] = [
    { name: 'lab 10', score: 3 }, { name: 'Lab 9', score: null }, { name: 'alpha', score: 7 }, { name: 'beta', score: 3 },
];
const names = (rows: Item[]) => rows.map((r) => r.name);

describe('sortRows', () => {
    it('sorts names case-blind with numbers in them as numbers', () => {
        expect(names(sortRows(items, columns, { key: 'name', direction: 'ascending' }))).toEqual(['alpha', 'beta', 'Lab 9', 'lab 10']);
        expect(names(sortRows(items, columns, { key: 'name', direction: 'descending' }))).toEqual(['lab 10', 'Lab 9', 'beta', 'alpha']);
    });

    it('sorts numbers by value, empty cells last in both directions, ties in their order', () => {
        expect(names(sortRows(items, columns, { key: 'score', direction: 'ascending' }))).toEqual(['lab 10', 'beta', 'alpha', 'Lab 9']);
        expect(names(sortRows(items, columns, { key: 'score', direction: 'descending' }))).toEqual(['alpha', 'lab 10', 'beta', 'Lab 9']);
        expect(names(items)).toEqual(['lab 10', 'Lab 9', 'alpha', 'beta']);   // the input stays as it was
    });
});

describe('nextOrder', () => {
    it('a click on another header sorts by it (numbers largest first), again the other way', () => {
        expect(nextOrder(null, 'name', columns)).toEqual({ key: 'name', direction: 'ascending' });
        expect(nextOrder({ key: 'name', direction: 'ascending' }, 'score', columns)).toEqual({ key: 'score', direction: 'descending' });
        expect(nextOrder({ key: 'score', direction: 'descending' }, 'score', columns)).toEqual({ key: 'score', direction: 'ascending' });
    });
});

describe('filterRows', () => {
    const models = [{ name: 'Position Servo', owner: 'admin' }, { name: 'Servo tuning', owner: 'stan' }, { name: 'Pump', owner: 'stella' }];
    const text = (m: { name: string; owner: string }) => `${m.name} ${m.owner}`;

    it('keeps the rows holding every word of the query, in any case', () => {
        expect(filterRows(models, 'servo', text).map((m) => m.name)).toEqual(['Position Servo', 'Servo tuning']);
        expect(filterRows(models, '  SERVO  stan ', text).map((m) => m.name)).toEqual(['Servo tuning']);
        expect(filterRows(models, 'stel', text).map((m) => m.name)).toEqual(['Pump']);
        expect(filterRows(models, 'valve', text)).toEqual([]);
        expect(filterRows(models, '   ', text)).toHaveLength(3);
    });
});

describe('sortableTable', () => {
    const body = (table: HTMLTableElement) => [...table.tBodies[0].rows].map((r) => r.cells[0].textContent);

    it('sorts by the clicked header and marks it (aria-sort), shows a search result in that order', () => {
        const table = sortableTable({ columns, rows: items, order: { key: 'name', direction: 'ascending' }, empty: 'none' });
        expect(body(table.element)).toEqual(['alpha', 'beta', 'Lab 9', 'lab 10']);
        const score = table.element.querySelector<HTMLElement>('th[data-column="score"]')!;
        score.querySelector('button')!.click();
        expect(score.getAttribute('aria-sort')).toBe('descending');
        expect(table.element.querySelector('th[data-column="name"]')!.hasAttribute('aria-sort')).toBe(false);
        expect(body(table.element)).toEqual(['alpha', 'lab 10', 'beta', 'Lab 9']);
        score.querySelector('button')!.click();
        expect(score.getAttribute('aria-sort')).toBe('ascending');
        expect(body(table.element)).toEqual(['lab 10', 'beta', 'alpha', 'Lab 9']);
        table.show(filterRows(items, 'lab', (r) => r.name));
        expect(body(table.element)).toEqual(['lab 10', 'Lab 9']);
        table.show([]);
        expect(body(table.element)).toEqual(['none']);
    });
});

describe('gradebook table', () => {
    const book: Gradebook = {
        assignments: [{ id: 1, title: 'Tune the servo' }, { id: 2, title: 'Pump' }],
        students: [
            { student: { id: 5, username: 'stella' }, cells: [{ points: 1, late: true }, { points: null, late: false }] },
            { student: { id: 4, username: 'stan' }, cells: [{ points: 3, late: false }, { points: 2.5, late: false }] },
            { student: { id: 6, username: 'sam' }, cells: [{ points: null, late: false }, { points: 4, late: false }] },
        ],
    };
    const usernames = (table: Element) => [...table.querySelectorAll('tbody tr')].map((r) => r.getAttribute('data-username'));

    it('totals each student as the CSV does (nothing handed in counts 0)', () => {
        expect(gradebookRows(book).map((r) => r.total)).toEqual([1, 5.5, 4]);
    });

    it('lists students by name, sorts by an assignment or the total when its header is clicked', () => {
        const table = gradebookTable(book);
        expect(usernames(table)).toEqual(['sam', 'stan', 'stella']);
        expect([...table.querySelectorAll('thead th')].map((th) => th.textContent)).toEqual(['Student ▲', 'Tune the servo', 'Pump', 'Total']);
        table.querySelector<HTMLButtonElement>('th[data-column="assignment-1"] button')!.click();
        expect(usernames(table)).toEqual(['stan', 'stella', 'sam']);   // not handed in: last
        table.querySelector<HTMLButtonElement>('th[data-column="total"] button')!.click();
        expect(usernames(table)).toEqual(['stan', 'sam', 'stella']);
        expect(table.querySelector('tr[data-username="stella"]')!.textContent).toContain('late');
    });
});
