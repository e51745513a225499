// A class's gradebook in the page, as the CSV has it: a row per student, a column per
// assignment (the grade where set, else the latest hand-in's score; "late" marked) and the
// total; every column sorts by a click on its header.
import { h } from '../ui/dom';
import { sortableTable, type Column } from '../ui/sortableTable';
import { formatNumber } from './format';
import type { Gradebook, GradebookCell, UserRef } from './types';

export interface GradebookRow { student: UserRef; cells: GradebookCell[]; total: number }

/** The rows with their totals (what was not handed in counts 0, as in the CSV). */
export function gradebookRows(book: Gradebook): GradebookRow[] {
    return book.students.map((s) => ({ ...s, total: s.cells.reduce((sum, c) => sum + (c.points ?? 0), 0) }));
}

export function gradebookColumns(book: Gradebook): Column<GradebookRow>[] {
    return [
        { key: 'student', label: 'Student', value: (r) => r.student.username },
        ...book.assignments.map((a, i): Column<GradebookRow> => ({
            key: `assignment-${a.id}`, label: a.title, numeric: true,
            value: (r) => r.cells[i]?.points ?? null,
            cell: (r) => {
                const cell = r.cells[i];
                if (!cell || cell.points === null) return h('span', { class: 'muted', title: 'Not handed in' }, '—');
                return h('span', {}, formatNumber(cell.points), cell.late ? h('span', { class: 'badge late' }, 'late') : null);
            },
        })),
        { key: 'total', label: 'Total', value: (r) => r.total, numeric: true, cell: (r) => formatNumber(r.total) },
    ];
}

export function gradebookTable(book: Gradebook): HTMLElement {
    if (book.students.length === 0) return h('p', { class: 'muted' }, 'No students yet.');
    return sortableTable({
        columns: gradebookColumns(book), rows: gradebookRows(book), order: { key: 'student', direction: 'ascending' },
        attrs: { 'data-testid': 'gradebook-table', class: 'model-table sortable-table gradebook-table' },
        rowAttrs: (r) => ({ 'data-username': r.student.username }),
    }).element;
}
