// The one undoable edit of the live controls: the model's list of them becomes `next` (add,
// move, change or remove one), written to the system parameter that stores them.
import { SetSystemParameter, type Command, type EditContext } from '../editor/commands';
import { controlsParameter, type LiveControl } from './liveControls';

export class ChangeLiveControls implements Command {
    readonly undoable = true;
    private readonly set: SetSystemParameter;

    constructor(next: readonly LiveControl[], readonly label: string) {
        this.set = new SetSystemParameter([], controlsParameter(next));
    }

    do(ctx: EditContext): Promise<void> { return this.set.do(ctx); }
    undo(ctx: EditContext): Promise<void> { return this.set.undo(ctx); }
}
