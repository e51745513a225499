// "Apply best point": a study's best parameters set on the open model as one editor command,
// so one undo takes all of them back (the editor's History runs it like any other edit).
import type { Command, EditContext } from '../editor/commands';
import { systemAt } from '../model/modelState';
import { parameterNamed } from './studyParameters';

interface Change { path: string[]; component: string | null; parameter: string; value: string; previous: string }

export class ApplyBestPoint implements Command {
    readonly undoable = true;
    readonly label: string;
    private changes: Change[] = [];

    /** `parameters`: the best point by study name (GainP.k, Sub$Comp.p, a system parameter). */
    constructor(private readonly parameters: Record<string, number>, studyId: number) {
        this.label = `Apply best point of study ${studyId}`;
    }

    async do(ctx: EditContext): Promise<void> {
        this.changes = [];
        for (const [name, value] of Object.entries(this.parameters)) {
            const place = parameterNamed(ctx.model(), name);
            if (!place) throw new Error(`The model has no parameter ${name}`);
            this.changes.push({ path: place.path, component: place.component, parameter: place.parameter, value: String(value), previous: place.text });
        }
        for (const c of this.changes) await this.set(ctx, c, c.value);
    }

    async undo(ctx: EditContext): Promise<void> {
        for (const c of [...this.changes].reverse()) await this.set(ctx, c, c.previous);
    }

    private async set(ctx: EditContext, c: Change, value: string): Promise<void> {
        if (c.component !== null) {
            await ctx.send({ type: 'parameter.set', system: c.path, component: c.component, parameter: c.parameter, value });
            return;
        }
        const old = systemAt(ctx.model(), c.path)?.parameters.find((p) => p.name === c.parameter);
        await ctx.send({ type: 'sysparam.set', system: c.path, name: c.parameter, value, param_type: old?.type, unit: old?.unit, description: old?.description });
    }
}
