// A bar between two panes stacked one over the other (the drawing and the run area): drag it,
// or focus it and use the arrow keys, to give one pane more height. The share of the lower
// pane is remembered in localStorage, so the layout comes back after a reload.
import { h } from './dom';

export const MIN_SHARE = 0.1;
export const MAX_SHARE = 0.9;
/** How far one arrow key moves the bar (a share of both panes' height). */
export const KEY_STEP = 0.05;

export function clampShare(share: number): number {
    return Math.min(MAX_SHARE, Math.max(MIN_SHARE, share));
}

/** The remembered share, or `fallback` when none (or garbage) is stored. */
export function loadShare(storage: Pick<Storage, 'getItem'>, key: string, fallback: number): number {
    const stored = Number(storage.getItem(key) ?? NaN);
    return Number.isFinite(stored) && stored > 0 ? clampShare(stored) : fallback;
}

/** The share after a key press on the bar; null for keys the bar does not use. */
export function shareAfterKey(share: number, key: string): number | null {
    switch (key) {
    case 'ArrowUp': return clampShare(share + KEY_STEP);
    case 'ArrowDown': return clampShare(share - KEY_STEP);
    case 'Home': return MAX_SHARE;
    case 'End': return MIN_SHARE;
    default: return null;
    }
}

export interface SplitterOptions {
    /** The pane above the bar and the one below it, whose heights the bar shares out. */
    upper: HTMLElement;
    lower: HTMLElement;
    storage: Storage;
    storageKey: string;
    /** The lower pane's share when nothing is remembered. */
    initial: number;
    label: string;
    /** Told the lower pane's share (0..1) at the start and on every change. */
    apply(share: number): void;
}

/** The bar, to be placed between the panes; the share is applied at once. */
export function createSplitter(o: SplitterOptions): HTMLElement {
    let share = loadShare(o.storage, o.storageKey, o.initial);
    const bar = h('div', {
        class: 'splitter', role: 'separator', tabindex: 0, 'aria-orientation': 'horizontal', 'aria-label': o.label,
        'aria-valuemin': String(MIN_SHARE * 100), 'aria-valuemax': String(MAX_SHARE * 100),
        title: 'Drag, or use ↑ ↓, to share the height between the drawing and the plots',
    });
    const set = (next: number, remember: boolean) => {
        share = clampShare(next);
        bar.setAttribute('aria-valuenow', String(Math.round(share * 100)));
        o.apply(share);
        if (remember) o.storage.setItem(o.storageKey, String(share));
    };
    // the share of the lower pane if the bar were at `y` (the bar's own height is neither pane's)
    const shareAt = (y: number) => {
        const top = o.upper.getBoundingClientRect().top;
        const bottom = o.lower.getBoundingClientRect().bottom;
        const both = bottom - top - bar.offsetHeight;
        return both > 0 ? (bottom - y - bar.offsetHeight / 2) / both : share;
    };
    bar.addEventListener('pointerdown', (e) => {
        if (e.button !== 0) return;
        e.preventDefault();
        bar.setPointerCapture(e.pointerId);
        bar.classList.add('dragging');
    });
    bar.addEventListener('pointermove', (e) => {
        if (bar.hasPointerCapture(e.pointerId)) set(shareAt(e.clientY), false);
    });
    const end = (e: PointerEvent) => {
        if (!bar.hasPointerCapture(e.pointerId)) return;
        bar.releasePointerCapture(e.pointerId);
        bar.classList.remove('dragging');
        set(share, true);
    };
    bar.addEventListener('pointerup', end);
    bar.addEventListener('pointercancel', end);
    bar.addEventListener('keydown', (e) => {
        const next = shareAfterKey(share, e.key);
        if (next === null) return;
        e.preventDefault();
        set(next, true);
    });
    set(share, false);
    return bar;
}
