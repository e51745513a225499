// Which parameter ports are drawn. As in Hopsan they stay hidden until the user shows them, for
// one component or for the whole model; a connected one is always drawn. The choice lasts for
// the session only: the model keeps no GUI-only state to save it in.
import type { SystemPath } from '../model/modelState';

export class ParameterPortVisibility {
    /** The toolbar's "Show parameter ports": every component's. */
    private everywhere = false;
    /** Components whose parameter ports the user showed, by subsystem path and name. */
    private readonly components = new Set<string>();
    private readonly listeners = new Set<() => void>();

    get shownEverywhere(): boolean { return this.everywhere; }

    showEverywhere(on: boolean): void {
        this.everywhere = on;
        this.emit();
    }

    /** Whether the user showed this component's parameter ports (or all of them). */
    shownFor(path: SystemPath, name: string): boolean {
        return this.everywhere || this.components.has(key(path, name));
    }

    /** Shows the components' parameter ports, or hides them if all of them show them already. */
    toggle(path: SystemPath, names: string[]): void {
        if (names.length === 0) return;
        const show = !names.every((name) => this.components.has(key(path, name)));
        for (const name of names) {
            if (show) this.components.add(key(path, name)); else this.components.delete(key(path, name));
        }
        this.emit();
    }

    subscribe(listener: () => void): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    private emit(): void {
        for (const listener of this.listeners) listener();
    }
}

function key(path: SystemPath, name: string): string {
    return [...path, name].join('$');
}
