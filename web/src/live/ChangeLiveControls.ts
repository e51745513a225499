// The one undoable edit of the live controls: the model's list of them becomes `next` (add,
// move, change or remove one), stored in the model's GUI data (model.controls). A model that
// still holds them in the old system parameter loses it with the first change (and gets it
// back with the undo).
import { sysParamRequest, type Command, type EditContext } from '../editor/commands';
import type { SysParam } from '../protocol/types';
import { legacyControlParameter, storedControls, type LiveControl } from './liveControls';

export class ChangeLiveControls implements Command {
    readonly undoable = true;
    private previous: ReturnType<typeof storedControls> = [];
    private legacy: SysParam | undefined;

    constructor(private readonly next: readonly LiveControl[], readonly label: string) {}

    async do(ctx: EditContext): Promise<void> {
        this.previous = ctx.model().system.live_controls ?? [];
        this.legacy = legacyControlParameter(ctx.model());
        await ctx.send({ type: 'model.controls', controls: storedControls(this.next) });
        if (this.legacy) await ctx.send({ type: 'sysparam.remove', system: [], name: this.legacy.name });
    }

    async undo(ctx: EditContext): Promise<void> {
        if (this.legacy) await ctx.send(sysParamRequest([], this.legacy));
        await ctx.send({ type: 'model.controls', controls: this.previous });
    }
}
