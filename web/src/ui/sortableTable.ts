// A table whose rows sort by the column whose header is clicked (again: the other way), and
// the search rule of the lists: every word of the query appears in the row's text. Empty
// cells sort last both ways, names compare as people read them ("lab 9" before "lab 10").
import { h } from './dom';

export type SortValue = string | number | null;

export interface Column<Row> {
    key: string;
    label: string;
    /** What the column sorts by; null: empty. */
    value(row: Row): SortValue;
    /** What the cell shows (default: the value). */
    cell?(row: Row): Node | string;
    /** Numbers: right-aligned, the first click sorts largest first. */
    numeric?: boolean;
    /** The first click sorts largest (newest) first; default: for numbers. */
    largestFirst?: boolean;
    /** false: the header does not sort (a column of buttons). */
    sortable?: boolean;
}

export type Direction = 'ascending' | 'descending';
export interface SortOrder { key: string; direction: Direction }

const collator = new Intl.Collator(undefined, { numeric: true, sensitivity: 'base' });

function compareValues(a: SortValue, b: SortValue): number {
    if (typeof a === 'number' && typeof b === 'number') return a - b;
    return collator.compare(String(a), String(b));
}

/** The rows in `order` (a copy; equal rows keep their order). */
export function sortRows<Row>(rows: readonly Row[], columns: readonly Column<Row>[], order: SortOrder): Row[] {
    const column = columns.find((c) => c.key === order.key);
    if (!column) return [...rows];
    const sign = order.direction === 'ascending' ? 1 : -1;
    return rows.map((row, index) => ({ row, index, value: column.value(row) }))
        .sort((x, y) => {
            const xEmpty = x.value === null || x.value === '';
            const yEmpty = y.value === null || y.value === '';
            if (xEmpty || yEmpty) return xEmpty === yEmpty ? x.index - y.index : xEmpty ? 1 : -1;
            return sign * compareValues(x.value, y.value) || x.index - y.index;
        })
        .map((entry) => entry.row);
}

/** The order after a click on column `key`'s header. */
export function nextOrder<Row>(current: SortOrder | null, key: string, columns: readonly Column<Row>[]): SortOrder {
    if (current?.key === key) return { key, direction: current.direction === 'ascending' ? 'descending' : 'ascending' };
    const column = columns.find((c) => c.key === key);
    return { key, direction: (column?.largestFirst ?? column?.numeric) ? 'descending' : 'ascending' };
}

/** The rows whose text holds every word of `query` (any case); all rows for an empty query. */
export function filterRows<Row>(rows: readonly Row[], query: string, text: (row: Row) => string): Row[] {
    const words = query.toLocaleLowerCase().split(/\s+/).filter((w) => w !== '');
    if (words.length === 0) return [...rows];
    return rows.filter((row) => {
        const haystack = text(row).toLocaleLowerCase();
        return words.every((w) => haystack.includes(w));
    });
}

export interface SortableTable<Row> {
    readonly element: HTMLTableElement;
    /** Shows these rows (e.g. after a search), in the current order. */
    show(rows: readonly Row[]): void;
}

export function sortableTable<Row>(options: {
    columns: Column<Row>[];
    rows: readonly Row[];
    order?: SortOrder;
    attrs?: Record<string, unknown>;
    rowAttrs?(row: Row): Record<string, unknown>;
    /** Shown as the only row when there are no rows. */
    empty?: string;
    /** Told each new order (to keep it when the table is built again). */
    onOrder?(order: SortOrder): void;
}): SortableTable<Row> {
    const { columns } = options;
    let order: SortOrder | null = options.order ?? null;
    let rows = options.rows;
    const body = h('tbody');
    const headers = columns.map((column) => h('th', { scope: 'col', class: column.numeric ? 'numeric' : '', 'data-column': column.key },
        column.sortable === false ? column.label : h('button', {
            class: 'sort-button', type: 'button', title: `Sort by ${column.label}`,
            onclick: () => {
                order = nextOrder(order, column.key, columns);
                options.onOrder?.(order);
                draw();
            },
        }, column.label, h('span', { class: 'sort-mark', 'aria-hidden': 'true' }))));
    const element = h('table', { class: 'model-table sortable-table', ...options.attrs },
        h('thead', {}, h('tr', {}, ...headers)), body);

    const draw = () => {
        headers.forEach((th, i) => {
            const sorted = order?.key === columns[i].key;
            if (sorted) th.setAttribute('aria-sort', order!.direction);
            else th.removeAttribute('aria-sort');
            const mark = th.querySelector('.sort-mark');
            if (mark) mark.textContent = sorted ? (order!.direction === 'ascending' ? ' ▲' : ' ▼') : '';
        });
        const shown = order ? sortRows(rows, columns, order) : rows;
        body.replaceChildren(...(shown.length === 0 && options.empty
            ? [h('tr', {}, h('td', { colspan: columns.length, class: 'muted' }, options.empty))]
            : shown.map((row) => h('tr', options.rowAttrs?.(row) ?? {},
                ...columns.map((c) => h('td', { class: c.numeric ? 'numeric' : '' }, c.cell ? c.cell(row) : String(c.value(row) ?? '')))))));
    };
    draw();
    return { element, show: (next) => { rows = next; draw(); } };
}
