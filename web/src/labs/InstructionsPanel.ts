// An assignment's instructions beside the editor of its copy: the title, what the student may
// change, and the Markdown text. It folds to a narrow strip to give the drawing room.
import { h } from '../ui/dom';
import { markdownBlock } from './markdown';
import { allowedText } from './AssignmentView';
import type { Assignment } from './types';

export function instructionsPanel(assignment: Assignment): HTMLElement {
    const panel = h('aside', { class: 'instructions-panel', 'aria-label': 'Instructions', 'data-testid': 'instructions-panel' });
    const show = (open: boolean) => {
        panel.dataset.open = String(open);
        toggle.setAttribute('aria-expanded', String(open));
        toggle.textContent = open ? 'Hide ▸' : '◂ Instructions';
        toggle.title = open ? 'Fold the instructions away' : 'Show the assignment\'s instructions';
        body.hidden = !open;
    };
    const toggle = h('button', { class: 'small instructions-toggle', 'data-testid': 'toggle-instructions', onclick: () => show(panel.dataset.open !== 'true') });
    const body = h('div', { class: 'instructions-body' },
        h('h2', {}, assignment.title),
        h('p', { class: 'muted allowed-text' }, allowedText(assignment)),
        assignment.instructions.trim() === ''
            ? h('p', { class: 'muted' }, 'No instructions.')
            : markdownBlock(assignment.instructions, { 'data-testid': 'editor-instructions' }));
    panel.append(h('div', { class: 'instructions-head' }, toggle), body);
    show(true);
    return panel;
}
