// A lab page as the router holds it: what it must stop when the user leaves (plots, timers).
import { h } from '../ui/dom';

export interface LabPage { dispose(): void }

export const noCleanup: LabPage = { dispose: () => undefined };

/** The page shown instead when the class or assignment cannot be read. */
export function errorPage(title: string, message: string, back: { href: string; label: string }): HTMLElement {
    return h('main', { class: 'error-page' }, h('h1', {}, title),
        h('p', { class: 'form-error', role: 'alert', 'data-testid': 'lab-error' }, message),
        h('a', { href: back.href }, back.label));
}

/** A section with a heading. */
export function section(title: string, testId: string, ...children: (Node | string | null | false | undefined)[]): HTMLElement {
    return h('section', { class: 'lab-section', 'data-testid': testId }, h('h2', {}, title), ...children);
}
