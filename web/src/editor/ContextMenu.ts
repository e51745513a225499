// A context menu: entries at the pointer, kept inside the window, with submenus. It closes on
// Escape, on a press elsewhere, on a scroll, resize or lost focus of the window. Keys as a
// desktop menu (WAI-ARIA menu pattern): ↑ ↓ Home End move, Enter or Space chooses, → opens
// a submenu and ← or Escape closes it, a letter jumps to the next entry starting with it, Tab
// closes. Keys do not reach the editor behind it while it is open.
import { h } from '../ui/dom';

export interface MenuEntry {
    label: string;
    /** The key that does the same, shown at the right. */
    shortcut?: string;
    /** A longer explanation (the entry's title). */
    hint?: string;
    /** What choosing it does; the menu closes first. */
    run?: () => void;
    /** The entries of a submenu, made when it opens. */
    submenu?: () => MenuItem[];
    /** Asked when the menu opens: a disabled entry is shown greyed and cannot be chosen. */
    disabled?: () => boolean;
    /** A toggle's state, shown as a check mark. */
    checked?: boolean;
    /** Names the entry for tests (data-entry). */
    id?: string;
}

export type MenuItem = MenuEntry | 'separator';

export interface Point { x: number; y: number }
export interface Size { width: number; height: number }

const MARGIN = 4;

/**
 * Where a box of `size` goes for a menu opened at `at`: right of and below the point; left of
 * or above it where the window ends (`flipX`: the x to use instead, for a submenu the parent's
 * left edge); never outside the window, which a box taller than it fills (then it scrolls).
 */
export function placeMenu(at: Point, size: Size, viewport: Size, flipX?: number): Point & { maxHeight?: number } {
    let x = at.x;
    if (x + size.width > viewport.width - MARGIN) x = (flipX ?? at.x) - size.width;
    x = Math.max(MARGIN, Math.min(x, viewport.width - MARGIN - size.width));
    const room = viewport.height - 2 * MARGIN;
    if (size.height > room) return { x, y: MARGIN, maxHeight: room };
    let y = at.y;
    if (y + size.height > viewport.height - MARGIN) y = flipX === undefined ? at.y - size.height : viewport.height - MARGIN - size.height;
    y = Math.max(MARGIN, Math.min(y, viewport.height - MARGIN - size.height));
    return { x, y };
}

interface Level {
    element: HTMLElement;
    entries: { entry: MenuEntry; el: HTMLElement; enabled: boolean }[];
    /** The entry of the level above that opened this one. */
    opener: HTMLElement | null;
}

function isEntry(item: MenuItem): item is MenuEntry {
    return item !== 'separator';
}

export class ContextMenu {
    private levels: Level[] = [];
    private returnFocus: HTMLElement | SVGElement | null = null;
    private readonly onPointerDown = (e: Event) => {
        if (!this.levels.some((l) => l.element.contains(e.target as Node))) this.close(false);
    };
    private readonly onWindowChange = () => this.close(false);
    private readonly onScroll = (e: Event) => {
        if (!this.levels.some((l) => l.element.contains(e.target as Node))) this.close(false);
    };

    constructor(private readonly host: HTMLElement = document.body) {}

    get isOpen(): boolean { return this.levels.length > 0; }
    /** The open menus, outermost first (for tests). */
    get elements(): HTMLElement[] { return this.levels.map((l) => l.element); }

    /** Opens `items` at a point of the window (client coordinates); `label` names the menu for screen readers. */
    open(items: MenuItem[], at: Point, label: string): void {
        const previous = document.activeElement as HTMLElement | SVGElement | null;
        this.close(false);
        this.returnFocus = previous;
        this.addLevel(items, at, label, null);
        document.addEventListener('pointerdown', this.onPointerDown, true);
        document.addEventListener('scroll', this.onScroll, true);
        window.addEventListener('resize', this.onWindowChange);
        window.addEventListener('blur', this.onWindowChange);
        this.focusIndex(0, this.firstEnabled(0, 1));
    }

    /** Closes every level; `restoreFocus`: focus goes back where it was before the menu opened. */
    close(restoreFocus = true): void {
        if (this.levels.length === 0) return;
        for (const level of this.levels) level.element.remove();
        this.levels = [];
        document.removeEventListener('pointerdown', this.onPointerDown, true);
        document.removeEventListener('scroll', this.onScroll, true);
        window.removeEventListener('resize', this.onWindowChange);
        window.removeEventListener('blur', this.onWindowChange);
        const target = this.returnFocus;
        this.returnFocus = null;
        if (restoreFocus && target && target.isConnected) target.focus({ preventScroll: true });
    }

    private addLevel(items: MenuItem[], at: Point, label: string, opener: HTMLElement | null): Level {
        const element = h('div', { class: 'context-menu', role: 'menu', 'aria-label': label, tabindex: -1 });
        const level: Level = { element, entries: [], opener };
        const depth = this.levels.length;
        // separators only between entries, never two in a row
        const cleaned = items.filter((item, i) => isEntry(item) || (i > 0 && i < items.length - 1 && isEntry(items[i - 1])));
        for (const item of cleaned) {
            if (!isEntry(item)) {
                element.append(h('div', { class: 'context-menu-separator', role: 'separator' }));
                continue;
            }
            const enabled = !(item.disabled?.() ?? false) && (item.run !== undefined || item.submenu !== undefined);
            const el = h('div', {
                class: `context-menu-item${item.submenu ? ' has-submenu' : ''}`,
                role: item.checked === undefined ? 'menuitem' : 'menuitemcheckbox',
                tabindex: -1,
                'aria-disabled': enabled ? undefined : 'true',
                'aria-haspopup': item.submenu ? 'menu' : undefined,
                'aria-expanded': item.submenu ? 'false' : undefined,
                'aria-checked': item.checked === undefined ? undefined : String(item.checked),
                title: item.hint,
                'data-entry': item.id,
            },
            h('span', { class: 'context-menu-check', 'aria-hidden': 'true' }, item.checked ? '✓' : ''),
            h('span', { class: 'context-menu-label' }, item.label),
            h('span', { class: 'context-menu-shortcut', 'aria-hidden': item.submenu ? 'true' : undefined }, item.submenu ? '▸' : item.shortcut ?? ''));
            if (item.shortcut && !item.submenu) el.setAttribute('aria-keyshortcuts', item.shortcut);
            const index = level.entries.length;
            level.entries.push({ entry: item, el, enabled });
            el.addEventListener('pointerenter', () => {
                this.closeFrom(depth + 1);
                this.focusIndex(depth, index);
                if (enabled && item.submenu) this.openSubmenu(depth, index, false);
            });
            el.addEventListener('click', (e) => {
                e.stopPropagation();
                this.choose(depth, index);
            });
            element.append(el);
        }
        element.addEventListener('keydown', (e) => this.onKey(e, depth));
        element.addEventListener('contextmenu', (e) => e.preventDefault());
        this.host.append(element);
        this.levels.push(level);
        this.position(level, at);
        return level;
    }

    private position(level: Level, at: Point): void {
        const { element, opener } = level;
        element.style.left = '0px';
        element.style.top = '0px';
        const box = element.getBoundingClientRect();
        const viewport = { width: document.documentElement.clientWidth || innerWidth, height: document.documentElement.clientHeight || innerHeight };
        const parentLeft = opener ? opener.closest('.context-menu')!.getBoundingClientRect().left : undefined;
        const spot = placeMenu(at, { width: box.width, height: box.height }, viewport, parentLeft);
        element.style.left = `${spot.x}px`;
        element.style.top = `${spot.y}px`;
        if (spot.maxHeight !== undefined) element.style.maxHeight = `${spot.maxHeight}px`;
    }

    private openSubmenu(depth: number, index: number, focusFirst: boolean): void {
        const opener = this.levels[depth].entries[index];
        if (!opener.enabled || !opener.entry.submenu) return;
        if (this.levels[depth + 1]?.opener === opener.el) {
            if (focusFirst) this.focusIndex(depth + 1, this.firstEnabled(depth + 1, 1));
            return;
        }
        this.closeFrom(depth + 1);
        const r = opener.el.getBoundingClientRect();
        opener.el.setAttribute('aria-expanded', 'true');
        this.addLevel(opener.entry.submenu(), { x: r.right - 2, y: r.top - 4 }, opener.entry.label, opener.el);
        if (focusFirst) this.focusIndex(depth + 1, this.firstEnabled(depth + 1, 1));
    }

    private closeFrom(depth: number): void {
        while (this.levels.length > depth) {
            const level = this.levels.pop()!;
            level.element.remove();
            level.opener?.setAttribute('aria-expanded', 'false');
        }
    }

    private choose(depth: number, index: number): void {
        const { entry, enabled } = this.levels[depth].entries[index];
        if (!enabled) return;
        if (entry.submenu) {
            this.openSubmenu(depth, index, true);
            return;
        }
        this.close();
        entry.run?.();
    }

    private focused(depth: number): number {
        return this.levels[depth].entries.findIndex((e) => e.el === document.activeElement);
    }

    private focusIndex(depth: number, index: number): void {
        const level = this.levels[depth];
        if (!level) return;
        const target = level.entries[index]?.el ?? level.element;
        target.focus({ preventScroll: false });
    }

    /** The next enabled entry from `start` in `step` direction, wrapping; the first one when none is. */
    private firstEnabled(depth: number, step: 1 | -1, start = step === 1 ? 0 : this.levels[depth].entries.length - 1): number {
        const entries = this.levels[depth].entries;
        for (let k = 0; k < entries.length; ++k) {
            const i = (((start + k * step) % entries.length) + entries.length) % entries.length;
            if (entries[i].enabled) return i;
        }
        return -1;
    }

    private onKey(e: KeyboardEvent, depth: number): void {
        // the menu answers its keys; the editor's (R, Delete, Ctrl+Z …) wait until it is closed
        e.stopPropagation();
        const entries = this.levels[depth].entries;
        const current = this.focused(depth);
        const move = (step: 1 | -1) => this.focusIndex(depth, this.firstEnabled(depth, step, current < 0 ? (step === 1 ? 0 : entries.length - 1) : current + step));
        switch (e.key) {
        case 'ArrowDown': move(1); break;
        case 'ArrowUp': move(-1); break;
        case 'Home': this.focusIndex(depth, this.firstEnabled(depth, 1)); break;
        case 'End': this.focusIndex(depth, this.firstEnabled(depth, -1)); break;
        case 'ArrowRight':
            if (current >= 0 && entries[current].entry.submenu) this.openSubmenu(depth, current, true);
            break;
        case 'ArrowLeft':
            if (depth > 0) this.back(depth);
            break;
        case 'Escape':
            if (depth > 0) this.back(depth); else this.close();
            break;
        case 'Enter':
        case ' ':
            if (current >= 0) this.choose(depth, current);
            break;
        case 'Tab':
            this.close();
            break;
        default:
            if (e.key.length === 1 && !e.ctrlKey && !e.metaKey && !e.altKey) this.jumpTo(depth, e.key, current);
            else return;   // other keys (F5, Ctrl+…) keep the browser's meaning
        }
        e.preventDefault();
    }

    private back(depth: number): void {
        const opener = this.levels[depth].opener;
        this.closeFrom(depth);
        opener?.focus();
    }

    private jumpTo(depth: number, letter: string, current: number): void {
        const entries = this.levels[depth].entries;
        const wanted = letter.toLowerCase();
        for (let k = 1; k <= entries.length; ++k) {
            const i = (current + k + entries.length) % entries.length;
            if (entries[i].enabled && entries[i].entry.label.toLowerCase().startsWith(wanted)) {
                this.focusIndex(depth, i);
                return;
            }
        }
    }
}
