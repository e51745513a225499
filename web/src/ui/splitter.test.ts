// @vitest-environment jsdom
import { describe, expect, it } from 'vitest';
import { createSplitter, loadShare, MAX_SHARE, MIN_SHARE, shareAfterKey } from './splitter';
import { h } from './dom';

function memoryStorage(): Storage {
    const items = new Map<string, string>();
    return {
        get length() { return items.size; },
        key: (i: number) => [...items.keys()][i] ?? null,
        getItem: (k: string) => items.get(k) ?? null,
        setItem: (k: string, v: string) => { items.set(k, v); },
        removeItem: (k: string) => { items.delete(k); },
        clear: () => items.clear(),
    };
}

describe('splitter', () => {
    it('remembers a share within bounds, and ignores garbage', () => {
        const storage = memoryStorage();
        expect(loadShare(storage, 'k', 0.4)).toBe(0.4);
        storage.setItem('k', '0.7');
        expect(loadShare(storage, 'k', 0.4)).toBe(0.7);
        storage.setItem('k', '5');
        expect(loadShare(storage, 'k', 0.4)).toBe(MAX_SHARE);
        storage.setItem('k', 'wide');
        expect(loadShare(storage, 'k', 0.4)).toBe(0.4);
    });

    it('arrow keys move the bar a step, Home and End to the ends', () => {
        expect(shareAfterKey(0.4, 'ArrowUp')).toBeCloseTo(0.45);
        expect(shareAfterKey(0.4, 'ArrowDown')).toBeCloseTo(0.35);
        expect(shareAfterKey(0.12, 'ArrowDown')).toBe(MIN_SHARE);
        expect(shareAfterKey(0.4, 'Home')).toBe(MAX_SHARE);
        expect(shareAfterKey(0.4, 'End')).toBe(MIN_SHARE);
        expect(shareAfterKey(0.4, 'a')).toBeNull();
    });

    it('is a separator that applies, announces and stores the share set with the keyboard', () => {
        const storage = memoryStorage();
        storage.setItem('share', '0.5');
        const applied: number[] = [];
        const bar = createSplitter({ upper: h('div'), lower: h('div'), storage, storageKey: 'share', initial: 0.4, label: 'Resize', apply: (s) => applied.push(s) });
        expect(bar.getAttribute('role')).toBe('separator');
        expect(bar.getAttribute('aria-valuenow')).toBe('50');
        expect(applied).toEqual([0.5]);
        bar.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowUp', bubbles: true }));
        expect(applied.at(-1)).toBeCloseTo(0.55);
        expect(bar.getAttribute('aria-valuenow')).toBe('55');
        expect(Number(storage.getItem('share'))).toBeCloseTo(0.55);
    });
});
