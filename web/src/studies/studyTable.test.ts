import { describe, expect, it } from 'vitest';
import { sortRows } from '../ui/sortableTable';
import { columnRoles, mergeRows, shortNumber, studyColumns, studyRows } from './studyTable';
import { StudyClient } from './StudyClient';
import type { StudyTable } from './studyTypes';

const table: StudyTable = {
    columns: ['run', 'ok', 'GainI.k', 'GainP.k', 'Pos#out#Value:final', 'objective'],
    rows: [[0, 1, 0, 0.01, 0.69, 3], [1, 0, 0, 0.025, null, null], [2, 1, 0.001, 0.04, 0.72, 1.5]],
    errors: { 1: 'Divide: Division by zero' },
};

describe('the study results table', () => {
    it('tells parameters, outputs and the objective apart by the server\'s column names', () => {
        expect(columnRoles(table.columns)).toEqual({ parameters: ['GainI.k', 'GainP.k'], outputs: ['Pos#out#Value:final'], objective: true });
    });

    it('rows carry the failed run\'s error', () => {
        const rows = studyRows(table);
        expect(rows.map((r) => [r.run, r.ok, r.error])).toEqual([[0, true, ''], [1, false, 'Divide: Division by zero'], [2, true, '']]);
    });

    it('sorts by a numeric column, smallest first on the first click, a failed run\'s empty cell last both ways', () => {
        const columns = studyColumns(table.columns);
        const rows = studyRows(table);
        expect(sortRows(rows, columns, { key: 'objective', direction: 'ascending' }).map((r) => r.run)).toEqual([2, 0, 1]);
        expect(sortRows(rows, columns, { key: 'objective', direction: 'descending' }).map((r) => r.run)).toEqual([0, 2, 1]);
        expect(sortRows(rows, columns, { key: 'GainP.k', direction: 'descending' }).map((r) => r.run)).toEqual([2, 1, 0]);
        expect(columns.find((c) => c.key === 'objective')?.largestFirst).toBe(false);
    });

    it('shows 6 significant digits and whole numbers as they are', () => {
        expect(shortNumber(0.025000000000000001)).toBe('0.025');
        expect(shortNumber(0.69706117764272379)).toBe('0.697061');
        expect(shortNumber(12)).toBe('12');
        expect(shortNumber(null)).toBe('');
    });

    it('joins a progress event\'s rows: each run once, in run order', () => {
        const merged = mergeRows(table, undefined, [[4, 1, 0, 0.1, 0.8, 2], [2, 1, 0.001, 0.04, 0.72, 1.5], [3, 1, 0, 0.2, 0.9, 4]]);
        expect(merged.rows.map((r) => r[0])).toEqual([0, 1, 2, 3, 4]);
        const fromEmpty = mergeRows({ columns: [], rows: [], errors: {} }, table.columns, [[1, 1, 0, 0, 0, 0]]);
        expect(fromEmpty.columns).toEqual(table.columns);
    });

    it('the CSV download is the server\'s CSV of the study (17 digits), asked for as text/csv', async () => {
        const calls: unknown[][] = [];
        const client = new StudyClient({ call: (async (...args: unknown[]) => { calls.push(args); return 'run,ok\n0,1\n'; }) as never });
        expect(await client.tableCsv(7)).toBe('run,ok\n0,1\n');
        expect(calls).toEqual([['GET', '/studies/7/results?format=csv', undefined, undefined, 'text/csv']]);
    });
});
