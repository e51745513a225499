// The editor's keys, in one table: the key handler runs them, the context menus show them
// beside their entries and the help panel ("?") lists them, so the three never disagree.
export type ShortcutId =
    | 'save' | 'undo' | 'redo' | 'copy' | 'cut' | 'paste' | 'select-all' | 'group' | 'delete'
    | 'rotate-right' | 'rotate-left' | 'flip-horizontal' | 'flip-vertical'
    | 'parameter-ports' | 'all-parameter-ports' | 'names' | 'open' | 'fit' | 'menu' | 'help' | 'deselect';

export interface Shortcut {
    id: ShortcutId;
    /** As shown: "Shift+R", "Ctrl+Z". */
    keys: string;
    does: string;
    group: 'Edit' | 'Arrange' | 'View' | 'Help';
    /** Also taken while typing in a field (only Ctrl+S). */
    whileTyping?: true;
    /** Only with the focus on the canvas (or nowhere): Enter on a button is the button's. */
    onCanvas?: true;
    matches(e: KeyboardEvent): boolean;
}

const mod = (e: KeyboardEvent) => e.ctrlKey || e.metaKey;
const plain = (e: KeyboardEvent) => !e.ctrlKey && !e.metaKey && !e.altKey;
const key = (e: KeyboardEvent, k: string) => e.key.toLowerCase() === k;

export const SHORTCUTS: Shortcut[] = [
    { id: 'save', keys: 'Ctrl+S', does: 'Save', group: 'Edit', whileTyping: true, matches: (e) => mod(e) && key(e, 's') },
    { id: 'undo', keys: 'Ctrl+Z', does: 'Undo', group: 'Edit', matches: (e) => mod(e) && key(e, 'z') && !e.shiftKey },
    { id: 'redo', keys: 'Ctrl+Y', does: 'Redo (also Ctrl+Shift+Z)', group: 'Edit', matches: (e) => mod(e) && (key(e, 'y') || (key(e, 'z') && e.shiftKey)) },
    { id: 'copy', keys: 'Ctrl+C', does: 'Copy the selected components', group: 'Edit', matches: (e) => mod(e) && key(e, 'c') },
    { id: 'cut', keys: 'Ctrl+X', does: 'Cut the selected components', group: 'Edit', matches: (e) => mod(e) && key(e, 'x') },
    { id: 'paste', keys: 'Ctrl+V', does: 'Paste', group: 'Edit', matches: (e) => mod(e) && key(e, 'v') },
    { id: 'select-all', keys: 'Ctrl+A', does: 'Select all components', group: 'Edit', matches: (e) => mod(e) && key(e, 'a') },
    { id: 'delete', keys: 'Del', does: 'Delete the selection or the selected line (also Backspace)', group: 'Edit', matches: (e) => plain(e) && (e.key === 'Delete' || e.key === 'Backspace') },
    { id: 'group', keys: 'Ctrl+G', does: 'Group the selection into a subsystem', group: 'Edit', matches: (e) => mod(e) && key(e, 'g') },
    { id: 'rotate-right', keys: 'R', does: 'Rotate right (clockwise)', group: 'Arrange', matches: (e) => plain(e) && key(e, 'r') && !e.shiftKey },
    { id: 'rotate-left', keys: 'Shift+R', does: 'Rotate left (anticlockwise)', group: 'Arrange', matches: (e) => plain(e) && key(e, 'r') && e.shiftKey },
    { id: 'flip-horizontal', keys: 'F', does: 'Flip horizontally', group: 'Arrange', matches: (e) => plain(e) && key(e, 'f') && !e.shiftKey },
    { id: 'flip-vertical', keys: 'Shift+F', does: 'Flip vertically', group: 'Arrange', matches: (e) => plain(e) && key(e, 'f') && e.shiftKey },
    { id: 'open', keys: 'Enter', does: 'Parameters of the selected component (a subsystem: go inside)', group: 'View', onCanvas: true, matches: (e) => plain(e) && e.key === 'Enter' },
    { id: 'parameter-ports', keys: 'P', does: 'Show or hide the selected components\' parameter ports', group: 'View', matches: (e) => plain(e) && key(e, 'p') && !e.shiftKey },
    { id: 'all-parameter-ports', keys: 'Shift+P', does: 'Show or hide every parameter port', group: 'View', matches: (e) => plain(e) && key(e, 'p') && e.shiftKey },
    { id: 'names', keys: 'N', does: 'Show or hide the selected components\' names', group: 'View', matches: (e) => plain(e) && key(e, 'n') && !e.shiftKey },
    { id: 'fit', keys: 'Home', does: 'Zoom to fit', group: 'View', matches: (e) => plain(e) && e.key === 'Home' },
    { id: 'deselect', keys: 'Esc', does: 'Clear the selection; close a menu', group: 'View', matches: (e) => e.key === 'Escape' },
    { id: 'menu', keys: 'Shift+F10', does: 'Context menu of the selection (also the menu key)', group: 'Help', matches: (e) => (e.key === 'F10' && e.shiftKey) || e.key === 'ContextMenu' },
    { id: 'help', keys: '?', does: 'This list', group: 'Help', matches: (e) => !mod(e) && e.key === '?' },
];

/** Mouse gestures and keys handled elsewhere, listed in the help panel only. */
export const GESTURES: { keys: string; does: string }[] = [
    { keys: 'Right click', does: 'Context menu of a component, line, port or the canvas' },
    { keys: 'Wheel', does: 'Zoom' },
    { keys: 'Drag port to port', does: 'Connect' },
    { keys: 'Drag on empty canvas', does: 'Select the components in the box (with Shift: add them)' },
    { keys: 'Space+drag, middle drag', does: 'Pan' },
    { keys: 'Drag a line', does: 'Move a segment between corners, or a corner (right click: add or remove a corner)' },
    { keys: 'Drag a component', does: 'Move; guides show and snap when it lines up with another' },
    { keys: 'Click a port', does: 'Plot one of its variables' },
    { keys: 'Double-click', does: 'Parameters of a component; the inside of a subsystem' },
    { keys: 'Shift/Ctrl+click', does: 'Add to or take from the selection' },
    { keys: 'Ctrl+← / Ctrl+→', does: 'In a focused plot window: the previous or next run' },
    { keys: 'Menu keys', does: '↑ ↓ move, Enter chooses, → opens a submenu, ← or Esc closes it' },
];

const byId = new Map(SHORTCUTS.map((s) => [s.id, s]));

/** The keys of a shortcut, as shown in menus. */
export function keysOf(id: ShortcutId): string {
    return byId.get(id)!.keys;
}

/**
 * The shortcut a key press is, or null. `focus`: where the key was typed: keys typed into a
 * field are the field's (but Ctrl+S), Enter on a button is the button's.
 */
export function shortcutFor(e: KeyboardEvent, focus: 'field' | 'control' | 'canvas'): Shortcut | null {
    for (const s of SHORTCUTS) {
        if (focus === 'field' && !s.whileTyping) continue;
        if (focus === 'control' && s.onCanvas) continue;
        if (s.matches(e)) return s;
    }
    return null;
}
