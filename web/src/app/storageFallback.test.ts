import { describe, expect, it } from 'vitest';
import { memoryStorage, useMemoryStorageWhereRefused } from './storageFallback';

describe('storage a framed page is refused', () => {
    it('keeps items in memory like the browser storage', () => {
        const storage = memoryStorage();
        storage.setItem('tlmhub.token', 'abc');
        storage.setItem('other', '1');
        expect(storage.getItem('tlmhub.token')).toBe('abc');
        expect(storage.length).toBe(2);
        expect(storage.key(1)).toBe('other');
        storage.removeItem('other');
        expect(storage.getItem('other')).toBeNull();
        storage.clear();
        expect(storage.length).toBe(0);
    });

    it('replaces only the storage that throws on access, as a third-party frame gets', () => {
        const refusing = {} as Window & typeof globalThis;
        Object.defineProperty(refusing, 'sessionStorage', {
            configurable: true,
            get() { throw new DOMException('Access is denied for this document.', 'SecurityError'); },
        });
        const kept = memoryStorage();
        Object.defineProperty(refusing, 'localStorage', { configurable: true, value: kept });
        expect(useMemoryStorageWhereRefused(refusing)).toEqual(['sessionStorage']);
        refusing.sessionStorage.setItem('tlmhub.token', 't');
        expect(refusing.sessionStorage.getItem('tlmhub.token')).toBe('t');
        expect(refusing.localStorage).toBe(kept);
    });
});
