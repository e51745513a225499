import { describe, expect, it } from 'vitest';
import { colourAt, distinctValues, formsGrid, heatMapCells, heatMapGrid, scaleOf } from './heatMap';
import type { StudyTable } from './studyTypes';

// a 3 × 2 grid, the first parameter varying slowest, one run failed
const table: StudyTable = {
    columns: ['run', 'ok', 'A.k', 'B.k', 'Out#x:final'],
    rows: [[0, 1, 1, 10, 5], [1, 1, 1, 20, 6], [2, 1, 2, 10, 7], [3, 0, 2, 20, null], [4, 1, 3, 10, 9], [5, 1, 3, 20, 11]],
    errors: { 3: 'Divide: Division by zero' },
};

describe('a 2-D sweep as heat-map cells', () => {
    it('puts each run in the cell of its two parameter values; a failed run leaves its cell empty', () => {
        const grid = heatMapGrid(table, 'A.k', 'B.k', 'Out#x:final')!;
        expect(grid.xs).toEqual([1, 2, 3]);
        expect(grid.ys).toEqual([10, 20]);
        expect(grid.z).toEqual([[5, 7, 9], [6, null, 11]]);
        expect(grid.range).toEqual([5, 11]);
    });

    it('swapping the axes transposes the grid', () => {
        const grid = heatMapGrid(table, 'B.k', 'A.k', 'Out#x:final')!;
        expect(grid.xs).toEqual([10, 20]);
        expect(grid.z).toEqual([[5, 6], [7, null], [9, 11]]);
    });

    it('is null for a column the table lacks, and has no range without a finite value', () => {
        expect(heatMapGrid(table, 'A.k', 'C.k', 'Out#x:final')).toBeNull();
        const empty = heatMapGrid({ ...table, rows: table.rows.map((r) => [...r.slice(0, 4), null]) }, 'A.k', 'B.k', 'Out#x:final')!;
        expect(empty.range).toBeNull();
    });

    it('lays the cells out with the first y value at the bottom', () => {
        const grid = heatMapGrid(table, 'A.k', 'B.k', 'Out#x:final')!;
        const cells = heatMapCells(grid, { left: 10, top: 0, width: 300, height: 100 });
        expect(cells).toHaveLength(6);
        expect(cells[0]).toEqual({ ix: 0, iy: 0, x: 10, y: 50, width: 100, height: 50, value: 5 });
        expect(cells[5]).toEqual({ ix: 2, iy: 1, x: 210, y: 0, width: 100, height: 50, value: 11 });
    });

    it('the colour scale runs from dark violet to yellow and clamps', () => {
        expect(colourAt(0)).toBe('rgb(68, 1, 84)');
        expect(colourAt(1)).toBe('rgb(253, 231, 37)');
        expect(colourAt(-3)).toBe(colourAt(0));
        expect(colourAt(9)).toBe(colourAt(1));
        expect(scaleOf(8, [5, 11])).toBe(0.5);
        expect(scaleOf(3, [3, 3])).toBe(0.5);
    });
});

describe('a heat map of a sweep of more than two parameters, or of runs that form no grid', () => {
    const three: StudyTable = {
        columns: ['run', 'ok', 'A.k', 'B.k', 'C.k', 'Out#x:final'],
        rows: [[0, 1, 1, 10, 0, 1], [1, 1, 1, 10, 5, 2], [2, 1, 1, 20, 0, 3], [3, 1, 1, 20, 5, 4],
            [4, 1, 2, 10, 0, 5], [5, 1, 2, 10, 5, 6], [6, 1, 2, 20, 0, 7], [7, 1, 2, 20, 5, 8]],
        errors: {},
    };

    it('holds the other parameters at one value each: one slice of the grid', () => {
        expect(heatMapGrid(three, 'A.k', 'B.k', 'Out#x:final', { 'C.k': 0 })!.z).toEqual([[1, 5], [3, 7]]);
        expect(heatMapGrid(three, 'A.k', 'B.k', 'Out#x:final', { 'C.k': 5 })!.z).toEqual([[2, 6], [4, 8]]);
        expect(distinctValues(three, 'C.k')).toEqual([0, 5]);
    });

    it('a list sweep\'s diagonal is no grid; a grid with a failed run still is', () => {
        const diagonal: StudyTable = { columns: ['run', 'ok', 'A.k', 'B.k', 'Out'], rows: [[0, 1, 1, 10, 1], [1, 1, 2, 20, 2], [2, 1, 3, 30, 3]], errors: {} };
        expect(formsGrid(heatMapGrid(diagonal, 'A.k', 'B.k', 'Out')!)).toBe(false);
        expect(formsGrid(heatMapGrid(table, 'A.k', 'B.k', 'Out#x:final')!)).toBe(true);
    });
});
