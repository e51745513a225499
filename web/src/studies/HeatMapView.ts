// Draws a heat map (heatMap.ts) on a canvas: cells, axes named by the parameters with a tick per
// value (thinned when crowded), and a colour bar with the output's range beside it.
import { h } from '../ui/dom';
import { colourAt, formsGrid, heatMapCells, scaleOf, type HeatMapGrid } from './heatMap';
import { shortNumber } from './studyTable';

const MARGIN = { left: 78, right: 110, top: 28, bottom: 52 };

export function drawHeatMap(canvas: HTMLCanvasElement, grid: HeatMapGrid, cssWidth: number, cssHeight: number): void {
    const ratio = window.devicePixelRatio || 1;
    canvas.width = Math.round(cssWidth * ratio);
    canvas.height = Math.round(cssHeight * ratio);
    canvas.style.width = `${cssWidth}px`;
    canvas.style.height = `${cssHeight}px`;
    const g = canvas.getContext('2d');
    if (!g) return;
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, cssWidth, cssHeight);
    g.fillStyle = '#fff';
    g.fillRect(0, 0, cssWidth, cssHeight);
    const box = { left: MARGIN.left, top: MARGIN.top, width: cssWidth - MARGIN.left - MARGIN.right, height: cssHeight - MARGIN.top - MARGIN.bottom };
    g.font = '12px system-ui, sans-serif';
    g.fillStyle = '#222';
    g.textAlign = 'center';
    g.fillText(grid.zName, box.left + box.width / 2, 16);

    for (const cell of heatMapCells(grid, box)) {
        g.fillStyle = cell.value === null || !grid.range ? '#e4e4e4' : colourAt(scaleOf(cell.value, grid.range));
        // whole pixels, each cell up to where the next begins: no seams between cells
        const [x0, y0] = [Math.round(cell.x), Math.round(cell.y)];
        g.fillRect(x0, y0, Math.round(cell.x + cell.width) - x0, Math.round(cell.y + cell.height) - y0);
    }
    g.strokeStyle = '#555';
    g.strokeRect(box.left, box.top, box.width, box.height);

    // ticks at cell centres, at most one per 48 px (x) / 18 px (y)
    g.fillStyle = '#222';
    const every = (count: number, room: number, px: number) => Math.max(1, Math.ceil(count / Math.max(1, Math.floor(room / px))));
    const cw = box.width / grid.xs.length;
    const xStep = every(grid.xs.length, box.width, 48);
    g.textAlign = 'center';
    g.textBaseline = 'top';
    grid.xs.forEach((x, i) => {
        if (i % xStep !== 0) return;
        const px = box.left + (i + 0.5) * cw;
        g.fillRect(px, box.top + box.height, 1, 4);
        g.fillText(shortNumber(x), px, box.top + box.height + 6);
    });
    const ch = box.height / grid.ys.length;
    const yStep = every(grid.ys.length, box.height, 18);
    g.textAlign = 'right';
    g.textBaseline = 'middle';
    grid.ys.forEach((y, i) => {
        if (i % yStep !== 0) return;
        const py = box.top + box.height - (i + 0.5) * ch;
        g.fillRect(box.left - 4, py, 4, 1);
        g.fillText(shortNumber(y), box.left - 6, py);
    });
    // axis names: the parameters
    g.textAlign = 'center';
    g.textBaseline = 'alphabetic';
    g.font = '600 12px system-ui, sans-serif';
    g.fillText(grid.xName, box.left + box.width / 2, cssHeight - 10);
    g.save();
    g.translate(16, box.top + box.height / 2);
    g.rotate(-Math.PI / 2);
    g.fillText(grid.yName, 0, 0);
    g.restore();

    // colour bar: the output's range, low at the bottom
    g.font = '12px system-ui, sans-serif';
    const bar = { left: box.left + box.width + 24, top: box.top, width: 16, height: box.height };
    for (let i = 0; i < bar.height; ++i) {
        g.fillStyle = colourAt(1 - i / bar.height);
        g.fillRect(bar.left, bar.top + i, bar.width, 1.5);
    }
    g.strokeStyle = '#555';
    g.strokeRect(bar.left, bar.top, bar.width, bar.height);
    g.fillStyle = '#222';
    g.textAlign = 'left';
    g.textBaseline = 'middle';
    if (grid.range) {
        for (const t of [0, 0.25, 0.5, 0.75, 1]) {
            const value = grid.range[0] + t * (grid.range[1] - grid.range[0]);
            const py = bar.top + bar.height * (1 - t);
            g.fillRect(bar.left + bar.width, py, 4, 1);
            g.fillText(shortNumber(value), bar.left + bar.width + 6, py);
        }
    }
}

/** What the user chose to see: axes, colour, and the values the other parameters are held at. */
export interface HeatMapChoice { x?: string; y?: string; z?: string; held?: Map<string, number> }

/**
 * A heat map with choices of the axes, the output and, with more than two swept parameters, the
 * value each other parameter is held at; redrawn when one changes.
 */
export function heatMapView(options: {
    parameters: string[]; outputs: string[]; values(parameter: string): number[];
    grid: (x: string, y: string, z: string, fixed: Record<string, number>) => HeatMapGrid | null;
    /** The choices, kept by the caller: the map is drawn anew as rows come and keeps them. */
    choice: HeatMapChoice;
}): HTMLElement {
    const { choice } = options;
    const pick = (names: string[], chosen: string | undefined, fallback: string) => (chosen && names.includes(chosen) ? chosen : fallback);
    const select = (names: string[], chosen: string, testid: string) =>
        h('select', { 'data-testid': testid }, ...names.map((n) => h('option', { value: n, selected: n === chosen }, n)));
    const xSelect = select(options.parameters, pick(options.parameters, choice.x, options.parameters[0]), 'heat-map-x');
    const ySelect = select(options.parameters, pick(options.parameters, choice.y, options.parameters[1]), 'heat-map-y');
    const zSelect = select(options.outputs, pick(options.outputs, choice.z, options.outputs[0]), 'heat-map-output');
    const held = h('div', { class: 'study-choices' });
    const heldValues = (choice.held ??= new Map<string, number>());
    const canvas = h('canvas', { class: 'heat-map-canvas', 'data-testid': 'heat-map', role: 'img' });
    const note = h('p', { class: 'muted' });
    const drawHeld = () => {
        const others = options.parameters.filter((p) => p !== xSelect.value && p !== ySelect.value);
        held.replaceChildren(...others.map((p) => {
            const values = options.values(p);
            if (!heldValues.has(p) || !values.includes(heldValues.get(p)!)) heldValues.set(p, values[0]);
            const choice = h('select', { 'aria-label': `${p} held at`, onchange: (e: Event) => { heldValues.set(p, Number((e.target as HTMLSelectElement).value)); draw(); } },
                ...values.map((v) => h('option', { value: String(v), selected: v === heldValues.get(p) }, shortNumber(v))));
            return h('label', {}, `${p} = `, choice);
        }));
    };
    const draw = () => {
        Object.assign(choice, { x: xSelect.value, y: ySelect.value, z: zSelect.value });
        const fixed = Object.fromEntries([...heldValues].filter(([p]) => p !== xSelect.value && p !== ySelect.value));
        const grid = options.grid(xSelect.value, ySelect.value, zSelect.value, fixed);
        if (!grid) return;
        const grid2d = formsGrid(grid);
        canvas.hidden = !grid2d;
        note.textContent = grid2d ? '' : 'These runs do not fill a grid of the two parameters (a list or random sweep): sort the table instead.';
        canvas.dataset.cells = String(grid.xs.length * grid.ys.length);
        canvas.dataset.filled = String(grid.z.flat().filter((v) => v !== null).length);
        canvas.setAttribute('aria-label', `Heat map of ${grid.zName} over ${grid.xName} and ${grid.yName}`);
        if (grid2d) drawHeatMap(canvas, grid, 640, 380);
    };
    for (const s of [xSelect, ySelect]) s.addEventListener('change', () => { drawHeld(); draw(); });
    zSelect.addEventListener('change', draw);
    drawHeld();
    draw();
    return h('div', { class: 'heat-map-view' },
        h('div', { class: 'study-choices' }, h('label', {}, 'x ', xSelect), h('label', {}, 'y ', ySelect), h('label', {}, 'colour ', zSelect)),
        held, canvas, note);
}
