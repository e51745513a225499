// The help panel ("?" key or the toolbar's ? button): the editor's keys from the shortcut
// table and the mouse gestures. A modal dialog: Escape or the close button closes it, and the
// focus goes back where it was.
import { h } from '../ui/dom';
import { GESTURES, SHORTCUTS } from './shortcuts';

export class ShortcutHelp {
    readonly element: HTMLDialogElement;
    private returnFocus: Element | null = null;

    constructor() {
        const groups = [...new Set(SHORTCUTS.map((s) => s.group))];
        const close = h('button', { class: 'shortcut-help-close', 'aria-label': 'Close', title: 'Close (Esc)', onclick: () => this.close() }, '×');
        this.element = h('dialog', { class: 'shortcut-help', 'aria-labelledby': 'shortcut-help-title', 'data-testid': 'shortcut-help' },
            h('div', { class: 'shortcut-help-head' }, h('h2', { id: 'shortcut-help-title' }, 'Keyboard shortcuts'), close),
            h('div', { class: 'shortcut-help-body' },
                ...groups.map((group) => h('section', {},
                    h('h3', {}, group),
                    table(SHORTCUTS.filter((s) => s.group === group).map((s) => [s.keys, s.does])))),
                h('section', {}, h('h3', {}, 'Mouse'), table(GESTURES.map((g) => [g.keys, g.does])))),
            h('p', { class: 'muted shortcut-help-note' }, 'On a Mac, ⌘ works where Ctrl is written.'));
        // keys in the panel are the panel's, not the editor's
        this.element.addEventListener('keydown', (e) => e.stopPropagation());
        this.element.addEventListener('close', () => this.restoreFocus());
        // a click on the backdrop (outside the box) closes it
        this.element.addEventListener('click', (e) => { if (e.target === this.element) this.close(); });
    }

    get isOpen(): boolean { return this.element.open; }

    open(): void {
        if (this.element.open) return;
        this.returnFocus = document.activeElement;
        if (!this.element.isConnected) document.body.append(this.element);
        if (typeof this.element.showModal === 'function') this.element.showModal(); else this.element.setAttribute('open', '');
    }

    toggle(): void {
        if (this.element.open) this.close(); else this.open();
    }

    close(): void {
        if (!this.element.open) return;
        if (typeof this.element.close === 'function') this.element.close(); else this.element.removeAttribute('open');
        this.restoreFocus();
    }

    dispose(): void {
        this.close();
        this.element.remove();
    }

    private restoreFocus(): void {
        const target = this.returnFocus as HTMLElement | null;
        this.returnFocus = null;
        if (target?.isConnected && typeof target.focus === 'function') target.focus();
    }
}

function table(rows: [string, string][]): HTMLTableElement {
    return h('table', { class: 'shortcut-table' }, h('tbody', {},
        ...rows.map(([keys, does]) => h('tr', {},
            h('th', { scope: 'row' }, ...keys.split(/( \/ |\+)/).map((part) => (part === '+' || part === ' / ' ? part : h('kbd', {}, part)))),
            h('td', {}, does)))));
}
