// The editor's state: the open model (as the server holds it), the subsystem being viewed,
// the selection and the history. Every change goes through a command, one at a time.
import { History } from './History';
import type { Command, EditContext } from './commands';
import { applyEdit, systemAt, type EditRequestOf, type EditType, type SystemPath } from '../model/modelState';
import type { Model, System } from '../protocol/types';
import type { ReplyData } from '../protocol/requests.generated';

/** Sends an edit request to the server and resolves with the reply's data. */
export type Transport = <T extends EditType>(request: EditRequestOf<T>) => Promise<ReplyData<T>>;

export class EditorStore {
    readonly history = new History();
    selection = new Set<string>();
    private currentPath: SystemPath = [];
    /** Counts models opened into this store; views drop what they derived from an older one. */
    generation = 0;
    private queue: Promise<unknown> = Promise.resolve();
    private readonly listeners = new Set<() => void>();
    private readonly context: EditContext;

    constructor(private current: Model, private readonly transport: Transport) {
        this.context = {
            send: async <T extends EditType>(request: EditRequestOf<T>) => {
                const data = await this.transport(request);
                this.current = applyEdit(this.current, request, data);
                this.emit();
                return data;
            },
            model: () => this.current,
        };
        this.history.reset();
    }

    get model(): Model { return this.current; }
    get path(): SystemPath { return this.currentPath; }
    /** The system on screen. */
    get system(): System { return systemAt(this.current, this.currentPath) ?? this.current.system; }
    get dirty(): boolean { return this.history.dirty; }

    subscribe(listener: () => void): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    /** Runs a command after the ones already queued; rejects with the server's error. */
    execute(command: Command): Promise<void> {
        return this.enqueue(() => this.history.execute(command, this.context));
    }

    undo(): Promise<unknown> { return this.enqueue(() => this.history.undo(this.context)); }
    redo(): Promise<unknown> { return this.enqueue(() => this.history.redo(this.context)); }

    /** Waits for every queued command. */
    idle(): Promise<void> { return this.queue.then(() => undefined, () => undefined); }

    enterSystem(path: SystemPath): void {
        if (!systemAt(this.current, path)) return;
        this.currentPath = [...path];
        this.selection = new Set();
        this.emit();
    }

    select(names: Iterable<string>): void {
        this.selection = new Set(names);
        this.emit();
    }

    markSaved(): void {
        this.history.markSaved();
        this.emit();
    }

    /** A fresh model from the server (opened again): history and selection start over. */
    replaceModel(model: Model): void {
        this.current = model;
        this.generation += 1;
        this.currentPath = systemAt(model, this.currentPath) ? this.currentPath : [];
        this.selection = new Set();
        this.history.reset();
        this.emit();
    }

    /**
     * The model was opened again on a new socket (`saved` is what the server opened): the
     * unsaved commands are sent again on top of it, so the server's model is the one on screen
     * again and the history stays. True when that worked; false when the history cannot tell
     * or the server refused one: then the saved model is shown and the history starts over.
     */
    reopen(saved: Model): Promise<boolean> {
        return this.enqueue(async () => {
            const commands = this.history.sinceSaved();
            if (commands !== null) {
                this.current = saved;
                try {
                    for (const command of commands) await command.do(this.context);
                    // the replay recomputed what the commands keep for undo from the same states
                    return true;
                } catch {
                    // fall through: the saved model, a fresh history
                }
            }
            this.replaceModel(saved);
            return false;
        });
    }

    private enqueue<T>(work: () => Promise<T>): Promise<T> {
        const run = this.queue.then(work, work);
        this.queue = run.catch(() => undefined);
        return run.finally(() => this.emit());
    }

    private emit(): void {
        // names of removed components leave the selection
        const names = new Set(this.system.components.map((c) => c.name));
        for (const n of this.selection) if (!names.has(n)) this.selection.delete(n);
        for (const l of this.listeners) l();
    }
}
