// What may be edited in the open model: everything, or (a student's copy of an assignment
// whose edit mode is `parameters`) only the listed parameters within their bounds. The same
// rule as the server's (server/labs/ParameterLock, docs/labs.md "Locks"), asked by the
// editor before it offers or sends a change, so that a locked copy looks locked.
import { ApiError } from '../api/ApiError';
import type { AllowedParameter, Assignment } from '../labs/types';
import type { Transport } from './EditorStore';
import type { EditRequest, EditRequestOf, EditType, SystemPath } from '../model/modelState';

/** A change other than a parameter's value: what a menu entry, a button or a gesture does. */
export type StructuralEdit =
    | 'add' | 'delete' | 'move' | 'rotate' | 'flip' | 'connect' | 'disconnect' | 'rename'
    | 'group' | 'ungroup' | 'paste' | 'replace' | 'lines' | 'system-parameters' | 'settings' | 'live-controls';

/** The edits each request type makes (reading requests make none). */
const REQUEST_EDITS: Partial<Record<EditRequest['type'], StructuralEdit>> = {
    'model.settings': 'settings',
    'model.controls': 'live-controls',
    'component.add': 'add',
    'component.remove': 'delete',
    'component.rename': 'rename',
    'component.move': 'move',
    'connect': 'connect',
    'disconnect': 'disconnect',
    'connection.route': 'lines',
    'sysparam.remove': 'system-parameters',
    'model.group': 'group',
    'model.ungroup': 'ungroup',
};

/**
 * The name an assignment gives a parameter: `Comp.param`, `Sub$Comp.param` inside subsystem
 * Sub, a root system parameter by its name, a subsystem's as `Sub.name` (core/ParameterPath.h).
 */
export function parameterPath(system: SystemPath, component: string | null, parameter: string): string {
    if (component === null) {
        if (system.length === 0) return parameter;
        return [...system.slice(0, -1).map((s) => `${s}$`), `${system[system.length - 1]}.${parameter}`].join('');
    }
    return `${system.map((s) => `${s}$`).join('')}${component}.${parameter}`;
}

/** An input's start value as the editor names it (`GainP.k#Value`) is the parameter `GainP.k`. */
function canonicalName(name: string): string {
    return name.endsWith('#Value') && name.length > '#Value'.length ? name.slice(0, -'#Value'.length) : name;
}

/** The bounds in words, as shown beside the field: "0 … 0.1", "≥ 1", "≤ 5" or "". */
export function boundsText(rule: AllowedParameter): string {
    if (rule.min !== undefined && rule.max !== undefined) return `${rule.min} … ${rule.max}`;
    if (rule.min !== undefined) return `≥ ${rule.min}`;
    if (rule.max !== undefined) return `≤ ${rule.max}`;
    return '';
}

/** A plain decimal number, as the server reads a bounded value (no expressions, no names). */
function plainNumber(text: string): number | null {
    const value = Number(text.trim());
    return text.trim() !== '' && Number.isFinite(value) ? value : null;
}

export class EditPermissions {
    /** Anything may change (a model of one's own, a free assignment's copy). */
    static readonly free = new EditPermissions(null);

    /** Only these parameters may change, each within its bounds. */
    static lockedTo(allowed: AllowedParameter[]): EditPermissions {
        return new EditPermissions(allowed);
    }

    /** The rule for a model opened as a copy of `assignment`; `ownCopy`: the viewer is the student. */
    static forAssignment(assignment: Assignment | null, ownCopy: boolean): EditPermissions {
        return assignment && ownCopy && assignment.edit_mode === 'parameters'
            ? EditPermissions.lockedTo(assignment.parameters)
            : EditPermissions.free;
    }

    private constructor(private readonly allowed: AllowedParameter[] | null) {}

    /** True when only listed parameters may change. */
    get locked(): boolean { return this.allowed !== null; }

    /** May this kind of change be made? (A locked copy allows none of them.) */
    allows(_edit: StructuralEdit): boolean {
        return this.allowed === null;
    }

    /**
     * The rule of one parameter (a component's, or with `component` null a system parameter of
     * the system at `system`): its bounds, or null when it may not change.
     */
    parameterRule(system: SystemPath, component: string | null, parameter: string): AllowedParameter | null {
        const name = parameterPath(system, component, parameter);
        if (this.allowed === null) return { name };
        return this.allowed.find((p) => canonicalName(p.name) === canonicalName(name)) ?? null;
    }

    /** Why `value` may not be given to the parameter, in words; null when it may. */
    valueRefusal(system: SystemPath, component: string | null, parameter: string, value: string): string | null {
        const rule = this.parameterRule(system, component, parameter);
        const name = parameterPath(system, component, parameter);
        if (!rule) return `${name} is not one of the parameters this assignment lets you change`;
        if (rule.min === undefined && rule.max === undefined) return null;
        const number = plainNumber(value);
        if (number === null) return `${name} takes a number within ${boundsText(rule)} here, not '${value}'`;
        if ((rule.min !== undefined && number < rule.min) || (rule.max !== undefined && number > rule.max)) {
            return `${name} must stay within ${boundsText(rule)}`;
        }
        return null;
    }

    /** Why an edit request may not be sent, in words; null when it may. */
    requestRefusal<T extends EditType>(sent: EditRequestOf<T>): string | null {
        if (this.allowed === null) return null;
        const request = sent as EditRequest;
        if (request.type === 'parameter.set') {
            return this.valueRefusal(request.system ?? [], request.component, request.parameter, String(request.value));
        }
        if (request.type === 'sysparam.set') {
            return this.valueRefusal(request.system ?? [], null, request.name, String(request.value));
        }
        const edit = REQUEST_EDITS[request.type];
        return edit && !this.allows(edit) ? 'Only the parameters this assignment lists may change in your copy' : null;
    }
}

/** Sends what `permissions` allow; refuses the rest with the reason, as the server would (403 `locked`). */
export function permittedTransport(permissions: EditPermissions, send: Transport): Transport {
    return (request) => {
        const refusal = permissions.requestRefusal(request);
        return refusal ? Promise.reject(new ApiError('locked', refusal, 403)) : send(request);
    };
}
