// A study's results table as the sortable table shows it: one row per run, columns as the
// server names them (run, ok, parameters in name order, outputs `Var:stat`, objective).
import type { Column } from '../ui/sortableTable';
import type { StudyTable } from './studyTypes';

export interface StudyRow { run: number; ok: boolean; cells: (number | null)[]; error: string }

/** Which columns are parameters, outputs and the objective. */
export interface ColumnRoles { parameters: string[]; outputs: string[]; objective: boolean }

export function columnRoles(columns: readonly string[]): ColumnRoles {
    const rest = columns.filter((c) => c !== 'run' && c !== 'ok' && c !== 'objective');
    return {
        // outputs are always "Variable:value"; parameters come first and hold no colon
        parameters: rest.filter((c) => !c.includes(':')),
        outputs: rest.filter((c) => c.includes(':')),
        objective: columns.includes('objective'),
    };
}

export function studyRows(table: StudyTable): StudyRow[] {
    const runAt = table.columns.indexOf('run');
    const okAt = table.columns.indexOf('ok');
    return table.rows.map((cells) => {
        const run = Number(cells[runAt]);
        return { run, ok: cells[okAt] === 1, cells, error: table.errors[String(run)] ?? '' };
    });
}

/** A number as the table shows it: 6 significant digits (the CSV has all 17). */
export function shortNumber(n: number | null): string {
    if (n === null || n === undefined) return '';
    if (Number.isInteger(n) && Math.abs(n) < 1e9) return String(n);
    return String(Number(n.toPrecision(6)));
}

export function studyColumns(columns: readonly string[]): Column<StudyRow>[] {
    return columns.map((name, i): Column<StudyRow> => {
        if (name === 'ok') {
            return { key: name, label: 'ok', value: (r) => (r.ok ? 'yes' : 'failed'), cell: (r) => (r.ok ? 'yes' : `failed: ${r.error}`) };
        }
        return { key: name, label: name, numeric: true, largestFirst: false, value: (r) => r.cells[i] ?? null, cell: (r) => shortNumber(r.cells[i] ?? null) };
    });
}

/** Rows of a progress event joined to the table: each run once, in run order. */
export function mergeRows(table: StudyTable, columns: readonly string[] | undefined, rows: readonly (number | null)[][]): StudyTable {
    const cols = table.columns.length > 0 ? table.columns : [...(columns ?? [])];
    const runAt = cols.indexOf('run');
    const byRun = new Map(table.rows.map((r) => [r[runAt], r]));
    for (const r of rows) byRun.set(r[runAt], r);
    const merged = [...byRun.values()].sort((a, b) => Number(a[runAt]) - Number(b[runAt]));
    return { columns: cols, rows: merged, errors: table.errors };
}
