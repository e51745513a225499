// A variable whose unit would be one axis too many for the active plot window is not sent to a
// window opened somewhere out of sight: a bar at the top of the plots (next to the drawing where
// the port was clicked) asks whether it gets a new axis in that window or a new window.
import { h } from '../ui/dom';

/** A variable waiting for the user's choice. */
export interface PendingVariable { name: string; label?: string; unit: string }

/** The window the variables were meant for, as the bar needs to name it. */
export interface ChoiceTarget { readonly id: number; axisUnits(): string[] }

export class AxisChoice<W extends ChoiceTarget> {
    readonly element: HTMLElement;
    private target: W | null = null;
    private pending: PendingVariable[] = [];

    constructor(private readonly choose: {
        /** Into `target` anyway, each new unit on an axis of its own. */
        addAxis(target: W, variables: PendingVariable[]): void;
        newWindow(variables: PendingVariable[]): void;
    }) {
        this.element = h('div', { class: 'axis-choice', role: 'alert', 'data-testid': 'axis-choice', hidden: true });
    }

    /** Asks where `variable` goes; more variables for the same window join the question. */
    ask(target: W, variable: PendingVariable): void {
        if (target !== this.target) this.pending = [];
        this.target = target;
        if (!this.pending.some((p) => p.name === variable.name)) this.pending.push(variable);
        this.draw();
    }

    /** Drops the question (its window was closed, or the user answered). */
    dismiss(): void {
        this.target = null;
        this.pending = [];
        this.element.hidden = true;
        this.element.replaceChildren();
    }

    /** The window the question is about, if any. */
    get asking(): W | null { return this.target; }

    private draw(): void {
        const target = this.target!;
        const variables = [...this.pending];
        const units = target.axisUnits().map((u) => u || 'no unit');
        const first = `${variables[0].label ?? variables[0].name} [${variables[0].unit || 'no unit'}]`;
        const named = variables.length > 1 ? `${first} and ${variables.length - 1} more` : first;
        const answer = (act: () => void) => () => { this.dismiss(); act(); };
        this.element.hidden = false;
        this.element.replaceChildren(
            h('span', { class: 'axis-choice-text' }, `${named}: Plot ${target.id} has ${units.length} axes already (${units.join(', ')}).`),
            h('button', { class: 'small primary', onclick: answer(() => this.choose.addAxis(target, variables)) }, `Add an axis to Plot ${target.id}`),
            h('button', { class: 'small', onclick: answer(() => this.choose.newWindow(variables)) }, 'Open a new plot window'),
            h('button', { class: 'small', onclick: () => this.dismiss() }, 'Cancel'));
    }
}
