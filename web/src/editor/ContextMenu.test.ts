// @vitest-environment jsdom
import { afterEach, describe, expect, it, vi } from 'vitest';
import { ContextMenu, placeMenu, type MenuItem } from './ContextMenu';

const press = (key: string, init: KeyboardEventInit = {}) => {
    const target = document.activeElement ?? document.body;
    const event = new KeyboardEvent('keydown', { key, bubbles: true, cancelable: true, ...init });
    target.dispatchEvent(event);
    return event;
};
const focusedLabel = () => (document.activeElement as HTMLElement | null)?.querySelector('.context-menu-label')?.textContent;

function fixture() {
    const ran: string[] = [];
    const entry = (label: string, extra: Partial<Extract<MenuItem, object>> = {}): MenuItem => ({ label, id: label, run: () => ran.push(label), ...extra });
    const items: MenuItem[] = [
        entry('Rotate right', { shortcut: 'R' }),
        entry('Rotate left'),
        'separator',
        entry('Delete', { disabled: () => true }),
        {
            label: 'Replace with', id: 'replace',
            submenu: () => [entry('4/3 valve, neutral to tank'), entry('4/2 valve')],
        },
        entry('Flip horizontally'),
    ];
    const outside = document.createElement('button');
    document.body.append(outside);
    outside.focus();
    const menu = new ContextMenu();
    menu.open(items, { x: 10, y: 10 }, 'Valve menu');
    return { menu, ran, outside };
}

afterEach(() => { document.body.replaceChildren(); });

describe('context menu keys', () => {
    it('opens with the first entry in focus and moves with the arrows, skipping disabled entries and wrapping', () => {
        const { menu } = fixture();
        expect(menu.elements[0].getAttribute('role')).toBe('menu');
        expect(menu.elements[0].getAttribute('aria-label')).toBe('Valve menu');
        expect(focusedLabel()).toBe('Rotate right');
        press('ArrowDown');
        expect(focusedLabel()).toBe('Rotate left');
        press('ArrowDown');   // Delete is disabled: skipped
        expect(focusedLabel()).toBe('Replace with');
        press('ArrowDown');
        expect(focusedLabel()).toBe('Flip horizontally');
        press('ArrowDown');   // wraps to the top
        expect(focusedLabel()).toBe('Rotate right');
        press('ArrowUp');
        expect(focusedLabel()).toBe('Flip horizontally');
        press('Home');
        expect(focusedLabel()).toBe('Rotate right');
        press('End');
        expect(focusedLabel()).toBe('Flip horizontally');
    });

    it('Enter runs the entry, closes the menu and gives the focus back', () => {
        const { menu, ran, outside } = fixture();
        press('ArrowDown');
        press('Enter');
        expect(ran).toEqual(['Rotate left']);
        expect(menu.isOpen).toBe(false);
        expect(document.querySelector('.context-menu')).toBeNull();
        expect(document.activeElement).toBe(outside);
    });

    it('a letter jumps to the next entry starting with it', () => {
        fixture();
        press('f');
        expect(focusedLabel()).toBe('Flip horizontally');
        press('r');
        expect(focusedLabel()).toBe('Rotate right');
        press('r');
        expect(focusedLabel()).toBe('Rotate left');
        press('R');
        expect(focusedLabel()).toBe('Replace with');
    });

    it('→ opens a submenu on its first entry, ← closes it onto its entry, Enter there runs its entry', () => {
        const { menu, ran } = fixture();
        press('End');
        press('ArrowUp');
        expect(focusedLabel()).toBe('Replace with');
        press('ArrowRight');
        expect(menu.elements).toHaveLength(2);
        expect(menu.elements[1].getAttribute('aria-label')).toBe('Replace with');
        expect(focusedLabel()).toBe('4/3 valve, neutral to tank');
        expect(document.querySelector('[data-entry="replace"]')!.getAttribute('aria-expanded')).toBe('true');
        press('ArrowLeft');
        expect(menu.elements).toHaveLength(1);
        expect(focusedLabel()).toBe('Replace with');
        press('Enter');   // Enter on a submenu entry opens it too
        press('ArrowDown');
        press('Enter');
        expect(ran).toEqual(['4/2 valve']);
        expect(menu.isOpen).toBe(false);
    });

    it('Escape closes a submenu first, then the menu; keys do not reach the page behind', () => {
        const { menu } = fixture();
        const behind = vi.fn();
        document.addEventListener('keydown', behind);
        press('r');
        press('r');
        press('ArrowRight');
        expect(menu.elements).toHaveLength(2);
        press('Escape');
        expect(menu.elements).toHaveLength(1);
        expect(focusedLabel()).toBe('Replace with');
        press('Escape');
        expect(menu.isOpen).toBe(false);
        expect(behind).not.toHaveBeenCalled();
        document.removeEventListener('keydown', behind);
    });

    it('a disabled entry is marked and does nothing when clicked', () => {
        const { menu, ran } = fixture();
        const del = document.querySelector<HTMLElement>('[data-entry="Delete"]')!;
        expect(del.getAttribute('aria-disabled')).toBe('true');
        del.click();
        expect(ran).toEqual([]);
        expect(menu.isOpen).toBe(true);
    });

    it('closes on a press elsewhere, not on a press inside', () => {
        const { menu, outside } = fixture();
        menu.elements[0].dispatchEvent(new Event('pointerdown', { bubbles: true }));
        expect(menu.isOpen).toBe(true);
        outside.dispatchEvent(new Event('pointerdown', { bubbles: true }));
        expect(menu.isOpen).toBe(false);
    });

    it('Tab closes it', () => {
        const { menu } = fixture();
        press('Tab');
        expect(menu.isOpen).toBe(false);
    });
});

describe('menu placement', () => {
    const viewport = { width: 1000, height: 700 };
    const size = { width: 220, height: 300 };

    it('opens right of and below the pointer where it fits', () => {
        expect(placeMenu({ x: 100, y: 100 }, size, viewport)).toEqual({ x: 100, y: 100 });
    });

    it('opens left of and above the pointer at the window\'s right and bottom edge', () => {
        expect(placeMenu({ x: 900, y: 600 }, size, viewport)).toEqual({ x: 680, y: 300 });
    });

    it('a submenu that does not fit right of its menu goes to the menu\'s left', () => {
        expect(placeMenu({ x: 950, y: 100 }, size, viewport, 730)).toEqual({ x: 510, y: 100 });
    });

    it('never leaves the window; a menu taller than the window scrolls', () => {
        const at = placeMenu({ x: 5, y: 50 }, { width: 220, height: 900 }, viewport);
        expect(at).toEqual({ x: 5, y: 4, maxHeight: 692 });
        const corner = placeMenu({ x: 150, y: 150 }, size, { width: 200, height: 200 });
        expect(corner.x).toBeGreaterThanOrEqual(4);
        expect(corner.y).toBeGreaterThanOrEqual(4);
    });
});
