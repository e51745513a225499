// Which component names are hidden on the canvas ("Hide name" in a component's menu). Hopsan
// keeps this in the .hmf (<nametext visible>), but the model the server sends carries no such
// field, so here it lasts for the session only, like the parameter ports' visibility.
import type { SystemPath } from '../model/modelState';

export class NameVisibility {
    private readonly hidden = new Set<string>();
    private readonly listeners = new Set<() => void>();

    hiddenFor(path: SystemPath, name: string): boolean {
        return this.hidden.has(key(path, name));
    }

    /** Hides the names, or shows them if all of them are hidden already. */
    toggle(path: SystemPath, names: string[]): void {
        if (names.length === 0) return;
        const hide = !names.every((name) => this.hidden.has(key(path, name)));
        for (const name of names) {
            if (hide) this.hidden.add(key(path, name)); else this.hidden.delete(key(path, name));
        }
        for (const listener of this.listeners) listener();
    }

    subscribe(listener: () => void): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }
}

function key(path: SystemPath, name: string): string {
    return [...path, name].join('$');
}
