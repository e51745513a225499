// "Share with class…" in live mode (docs/live-sessions.md, "In a lab"): the class whose
// members may watch the session read-only. Offered: the classes the user teaches that are not
// archived (the server refuses the others: forbidden, archived).
import { h } from '../ui/dom';
import { runModalForm } from '../ui/modalForm';
import type { LabClass } from '../labs/types';

/** The classes a live session may be shared with, by their names. */
export function shareableClasses(classes: LabClass[]): LabClass[] {
    return classes.filter((c) => c.role === 'teacher' && !c.archived).sort((a, b) => a.name.localeCompare(b.name));
}

/** Asks which class to share with; resolves with its id, or null when cancelled. */
export function askForClass(classes: LabClass[]): Promise<number | null> {
    const dialog = h('dialog', { class: 'live-share-dialog', 'data-testid': 'live-share-dialog', 'aria-label': 'Share with class' });
    const choice = h('select', { 'aria-label': 'Class' }, ...classes.map((c) => h('option', { value: String(c.id) }, c.name)));
    const ok = h('button', { class: 'primary', type: 'submit', 'data-testid': 'live-share-ok' }, 'Share');
    const cancel = h('button', { type: 'button' }, 'Cancel');
    const form = h('form', { method: 'dialog' },
        h('h2', {}, 'Share with class'),
        h('p', { class: 'muted' }, 'The class\'s members can watch this live session read-only until it ends or you stop sharing.'),
        h('label', {}, 'Class ', choice),
        h('div', { class: 'dialog-buttons' }, ok, cancel));
    dialog.append(form);
    return runModalForm(dialog, form, cancel, () => Number(choice.value), choice);
}
