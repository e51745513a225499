// Web storage that may be refused. A browser that blocks third-party cookies also refuses
// sessionStorage and localStorage to a page in another site's frame (Chromium throws a
// SecurityError on first access): the LTI launch page inside a learning platform's course
// page. There the app keeps its login and layouts in memory instead, for as long as the frame
// stays open, rather than failing to start.

/** A Storage held in memory (the same methods as the browser's). */
export function memoryStorage(): Storage {
    const items = new Map<string, string>();
    return {
        get length() { return items.size; },
        clear: () => items.clear(),
        getItem: (key: string) => items.get(key) ?? null,
        key: (index: number) => [...items.keys()][index] ?? null,
        removeItem: (key: string) => { items.delete(key); },
        setItem: (key: string, value: string) => { items.set(key, String(value)); },
    };
}

/** Replaces each of window.sessionStorage and window.localStorage that the browser refuses with one in memory. */
export function useMemoryStorageWhereRefused(target: Window & typeof globalThis = window): string[] {
    const replaced: string[] = [];
    for (const name of ['sessionStorage', 'localStorage'] as const) {
        try {
            void target[name].length;
        } catch {
            Object.defineProperty(target, name, { value: memoryStorage(), configurable: true });
            replaced.push(name);
        }
    }
    return replaced;
}
