// Undo/redo stacks of executed commands, and the revision the store was saved at (dirty state).
import type { Command, EditContext } from './commands';

interface Entry { command: Command; revision: number }

export class History {
    private done: Entry[] = [];
    private undone: Entry[] = [];
    private counter = 0;
    private base = 0;          // revision of the state below the undo stack
    private saved = 0;

    /** Runs a command and records it; a failed command changes nothing in the history. */
    async execute(command: Command, ctx: EditContext): Promise<void> {
        await command.do(ctx);
        const revision = ++this.counter;
        if (command.undoable) {
            this.done.push({ command, revision });
        } else {
            this.done = [];
            this.base = revision;
        }
        this.undone = [];
    }

    async undo(ctx: EditContext): Promise<Command | null> {
        const entry = this.done.pop();
        if (!entry) return null;
        try {
            await entry.command.undo(ctx);
        } catch (e) {
            // the server refused: the state is unknown, so nothing before it can be undone safely
            this.done = [];
            this.undone = [];
            this.base = ++this.counter;
            throw e;
        }
        this.undone.push(entry);
        return entry.command;
    }

    async redo(ctx: EditContext): Promise<Command | null> {
        const entry = this.undone.pop();
        if (!entry) return null;
        try {
            await entry.command.do(ctx);
        } catch (e) {
            this.undone = [];
            throw e;
        }
        this.done.push(entry);
        return entry.command;
    }

    get canUndo(): boolean { return this.done.length > 0; }
    get canRedo(): boolean { return this.undone.length > 0; }
    get undoLabel(): string | undefined { return this.done.at(-1)?.command.label; }
    get redoLabel(): string | undefined { return this.undone.at(-1)?.command.label; }

    /** Identifies the current state: equal revisions mean equal models. */
    get revision(): number { return this.done.at(-1)?.revision ?? this.base; }

    markSaved(): void { this.saved = this.revision; }

    /**
     * The commands that lead from the saved state to the current one, oldest first; null when
     * the history cannot tell (the saved state was undone, or lies before a command that cannot
     * be undone). A new socket opens the saved model; these bring it back to what is on screen.
     */
    sinceSaved(): Command[] | null {
        if (this.saved === this.revision) return [];
        if (this.saved === this.base) return this.done.map((e) => e.command);
        const at = this.done.findIndex((e) => e.revision === this.saved);
        return at < 0 ? null : this.done.slice(at + 1).map((e) => e.command);
    }
    get dirty(): boolean { return this.revision !== this.saved; }

    /** Forget everything (a new model was opened); the current state counts as saved. */
    reset(): void {
        this.done = [];
        this.undone = [];
        this.base = ++this.counter;
        this.saved = this.base;
    }
}
