// Which two runs a plot window subtracts (Hopsan's "subtract generations"): a toggle button for
// the window's header and, while it is on, a bar with run A and run B to pick. Unpicked, A is
// the run the window shows and B the one before it in time, so stepping moves both along.
import { differencePair, type Generation } from './generations';
import { h } from '../ui/dom';

type Run = Generation & { readonly label: string };

export class DifferenceChoice {
    readonly button: HTMLButtonElement;
    readonly bar: HTMLElement;
    private readonly aSelect: HTMLSelectElement;
    private readonly bSelect: HTMLSelectElement;
    private on = false;
    /** Jobs the user picked; null follows the default of each side. */
    private picked: { a: number | null; b: number | null } = { a: null, b: null };
    /** The runs the selects list: rebuilt only when they change, so an open list stays open while a run streams. */
    private listed = '';

    constructor(private readonly changed: () => void) {
        this.button = h('button', {
            class: 'small', onclick: () => this.toggle(), 'aria-pressed': 'false', 'aria-label': 'Difference of two runs',
            title: 'Add the difference of two runs (A − B) for each variable',
        }, 'A−B');
        const select = (side: 'a' | 'b', label: string) => h('select', {
            'aria-label': label, name: `difference-${side}`,
            onchange: () => { this.picked[side] = Number(this.sideSelect(side).value); this.changed(); },
        });
        this.aSelect = select('a', 'Difference run A');
        this.bSelect = select('b', 'Difference run B');
        this.bar = h('div', { class: 'plot-difference', hidden: true }, 'Difference: ', this.aSelect, ' − ', this.bSelect);
    }

    private sideSelect(side: 'a' | 'b'): HTMLSelectElement { return side === 'a' ? this.aSelect : this.bSelect; }

    private toggle(): void {
        this.on = !this.on;
        this.picked = { a: null, b: null };
        this.button.setAttribute('aria-pressed', String(this.on));
        this.bar.hidden = !this.on;
        this.changed();
    }

    /** Runs A and B (oldest first in `runs`) while the difference is on; null when it is off or there is one run. */
    pair<T extends Run>(runs: readonly T[], shown: number | null): { a: T; b: T } | null {
        const fallback = differencePair(runs, shown);
        if (!this.on || !fallback) return null;
        const find = (job: number | null) => runs.find((r) => r.jobId === job);
        return { a: find(this.picked.a) ?? fallback.a, b: find(this.picked.b) ?? fallback.b };
    }

    /** Shows the runs to pick from, `pair` picked; the button works from two runs on. */
    draw(runs: readonly Run[], pair: { a: Run; b: Run } | null): void {
        this.button.disabled = runs.length < 2;
        if (!pair) return;
        const listed = runs.map((r) => `${r.jobId}:${r.label}`).join('|');
        for (const [select, run] of [[this.aSelect, pair.a], [this.bSelect, pair.b]] as const) {
            if (listed !== this.listed) select.replaceChildren(...runs.map((r) => h('option', { value: String(r.jobId) }, r.label)));
            select.value = String(run.jobId);
        }
        this.listed = listed;
    }
}
