// Right-hand panel: the selected component's name and parameters (values with units;
// numbers, expressions and system-parameter names; errors inline), or the system's
// parameters when nothing is selected. A refused value leaves the field at the model's value
// with the reason beside it. In a locked copy (EditPermissions) only the allowed parameters
// take input, their bounds beside them; everything else is read-only.
import { EditorStore } from './EditorStore';
import { RenameComponent, SetParameter, SetSystemParameter } from './commands';
import { errorText, h } from '../ui/dom';
import { displayNameOf } from '../model/appearance';
import { isParameterPort } from '../model/parameterPortPlacement';
import { parameterLabel, shortName, splitParameters } from './parameterLabels';
import { notFiniteError } from './finiteNumber';
import { boundsText, EditPermissions, type StructuralEdit } from './EditPermissions';
import { CONTROLS_PARAMETER } from '../live/liveControls';
import type { Component, PortRef, System } from '../protocol/types';

export interface PanelActions {
    rotate(): void;
    flip(): void;
    remove(): void;
    group(): void;
    ungroup(): void;
    plotPort(ref: PortRef, anchor: HTMLElement): void;
    /** Shows or hides the selected components' parameter ports. */
    toggleParameterPorts(): void;
    parameterPortsShown(name: string): boolean;
    /** Puts a live control bound to one of the component's values on the drawing (src/live/). */
    addLiveControl?(component: string): void;
}

export class ParameterPanel {
    /** The panel's content, inside `element` (see .parameter-panel-body in styles.css). */
    private readonly body = h('div', { class: 'parameter-panel-body' });
    readonly element = h('aside', { class: 'parameter-panel', 'aria-label': 'Parameters' }, this.body);
    private signature = '';
    /** Why the last value typed into a field was refused, until the field is changed again. */
    private readonly refused = new Map<string, string>();
    private nameError = '';

    constructor(private readonly store: EditorStore, private readonly actions: PanelActions,
        private readonly permissions: EditPermissions = EditPermissions.free) {
        store.subscribe(() => this.render());
        this.render();
    }

    focusName(): void {
        const input = this.element.querySelector<HTMLInputElement>('input[name="component-name"]');
        input?.focus();
        input?.select();
    }

    render(): void {
        const system = this.store.system;
        const selected = [...this.store.selection];
        const comp = selected.length === 1 ? system.components.find((c) => c.name === selected[0]) : undefined;
        const portsShown = comp ? this.actions.parameterPortsShown(comp.name) : false;
        const signature = JSON.stringify([this.store.path, selected, comp ?? system.parameters, this.nameError, [...this.refused], portsShown]);
        if (signature === this.signature) return;
        this.signature = signature;
        if (comp) this.body.replaceChildren(...this.componentView(comp));
        else if (selected.length > 1) this.body.replaceChildren(...this.multiView(selected.length));
        else this.body.replaceChildren(...this.systemView(system));
    }

    private run(work: Promise<void>, onError: (message: string) => void): void {
        work.catch((e) => onError(errorText(e)));
    }

    private componentView(comp: Component): HTMLElement[] {
        const path = this.store.path;
        const name = h('input', { name: 'component-name', value: comp.name, 'aria-label': 'Component name', readonly: !this.may('rename') });
        const commitName = () => {
            const wanted = name.value.trim();
            if (wanted === '' || wanted === comp.name || !this.may('rename')) return;
            if (this.store.system.components.some((c) => c.name === wanted) || this.store.system.ports.some((p) => p.name === wanted)) {
                this.nameError = `The name ${wanted} is already used in this system`;
                this.render();
                return;
            }
            const command = new RenameComponent(path, comp.name, wanted);
            this.run(this.store.execute(command).then(() => {
                this.nameError = '';
                this.store.select([command.newName]);
            }), (m) => { this.nameError = m; this.render(); });
        };
        name.addEventListener('keydown', (e) => { if (e.key === 'Enter') commitName(); if (e.key === 'Escape') name.value = comp.name; });
        name.addEventListener('change', commitName);

        const row = (p: Component['parameters'][number]) => {
            const key = `${comp.name}.${p.name}`;
            const refused = this.refused.get(key);
            const rule = this.permissions.parameterRule(path, comp.name, p.name);
            const input = this.valueField(`param-${p.name}`, `${p.name} value`, p.value, refused, rule !== null);
            const commit = () => {
                const value = input.value.trim();
                if (value === p.value) { if (refused) { this.refused.delete(key); this.render(); } return; }
                const notFinite = notFiniteError(`${comp.name}.${shortName(p)}`, p.type, value);
                if (notFinite) { this.refuse(key, notFinite); return; }
                this.run(this.store.execute(new SetParameter(path, comp.name, p.name, value)).then(() => {
                    this.refused.delete(key);
                    this.render();
                }), (message) => this.refuse(key, message));
            };
            if (rule) {
                input.addEventListener('keydown', (e) => { if (e.key === 'Enter') commit(); });
                input.addEventListener('change', commit);
            }
            const label = parameterLabel(p);
            return h('tr', { 'data-param': p.name, class: this.rowClass(rule !== null), title: `${shortName(p)}${p.description ? `: ${p.description}` : ''}` },
                h('th', {}, h('span', { class: 'param-label' }, label),
                    label !== shortName(p) ? h('span', { class: 'param-name' }, shortName(p)) : null),
                h('td', {}, input, this.boundsNote(rule), refused ? h('div', { class: 'field-error', role: 'alert' }, refused) : null),
                h('td', { class: 'unit' }, p.unit));
        };
        const { parameters, startValues } = splitParameters(comp.parameters);
        const table = (list: typeof parameters) => h('table', { class: 'param-table' }, h('tbody', {}, ...list.map(row)));

        const ports = comp.ports.map((p) => {
            const button: HTMLButtonElement = h('button', {
                class: 'small', title: 'Plot a variable of this port',
                onclick: () => this.actions.plotPort({ component: comp.name, port: p.name }, button),
            }, 'Plot');
            return h('li', { 'data-port-name': p.name }, `${p.name} `, h('span', { class: 'muted' }, `${p.node_type.replace(/^Node/, '')} ${p.kind}${p.multiport ? ' multi' : ''}`), ' ', button);
        });

        return [
            h('h2', {}, 'Component'),
            h('label', { class: 'stacked' }, 'Name', name),
            this.nameError ? h('div', { class: 'field-error', role: 'alert' }, this.nameError) : h('span'),
            h('p', { class: 'muted' }, `${displayNameOf(comp.type)} · ${comp.type} · ${comp.kind === 'system' ? 'subsystem' : `${comp.kind}-type`}`),
            h('div', { class: 'button-row' },
                h('button', { onclick: () => this.actions.rotate(), title: 'Rotate (R)', disabled: !this.may('rotate') }, 'Rotate'),
                h('button', { onclick: () => this.actions.flip(), title: 'Flip (F)', disabled: !this.may('flip') }, 'Flip'),
                comp.ports.some((p) => isParameterPort(comp, p)) ? h('button', {
                    onclick: () => this.actions.toggleParameterPorts(), title: 'Show or hide this component\'s parameter ports (P)',
                    'aria-pressed': String(this.actions.parameterPortsShown(comp.name)), 'data-testid': 'toggle-parameter-ports',
                }, 'Parameter ports') : null,
                comp.system ? h('button', { onclick: () => this.store.enterSystem([...path, comp.name]) }, 'Enter') : null,
                this.actions.addLiveControl && !comp.system ? h('button', {
                    onclick: () => this.actions.addLiveControl?.(comp.name), 'data-testid': 'add-live-control', disabled: !this.may('system-parameters'),
                    title: 'A slider, knob, switch or number field on the drawing that changes one of its values in live mode',
                }, 'Add live control') : null,
                comp.system ? h('button', { onclick: () => this.actions.ungroup(), 'data-testid': 'ungroup', disabled: !this.may('ungroup') }, 'Ungroup') : null,
                h('button', { class: 'danger', onclick: () => this.actions.remove(), title: 'Delete (Del)', disabled: !this.may('delete') }, 'Delete')),
            h('h3', {}, 'Parameters'),
            parameters.length ? table(parameters) : h('p', { class: 'muted' }, 'No parameters.'),
            ...(startValues.length ? [h('h3', {}, 'Start values'), h('div', { class: 'start-values', 'data-testid': 'start-values' }, table(startValues))] : []),
            h('h3', {}, 'Ports'),
            h('ul', { class: 'port-list' }, ...ports),
        ];
    }

    private multiView(count: number): HTMLElement[] {
        return [
            h('h2', {}, `${count} components selected`),
            h('div', { class: 'button-row' },
                h('button', { onclick: () => this.actions.rotate(), disabled: !this.may('rotate') }, 'Rotate'),
                h('button', { onclick: () => this.actions.flip(), disabled: !this.may('flip') }, 'Flip'),
                h('button', { onclick: () => this.actions.group(), 'data-testid': 'group', disabled: !this.may('group') }, 'Group into subsystem'),
                h('button', { class: 'danger', onclick: () => this.actions.remove(), disabled: !this.may('delete') }, 'Delete')),
            h('p', { class: 'muted' }, 'Ctrl+C / Ctrl+V copies them with the connections among them.'),
        ];
    }

    private systemView(system: System): HTMLElement[] {
        const path = this.store.path;
        // the live controls' parameter is drawn on the canvas, not listed
        const rows = system.parameters.filter((p) => p.name !== CONTROLS_PARAMETER).map((p) => {
            const key = `$sys.${p.name}`;
            const refused = this.refused.get(key);
            const rule = this.permissions.parameterRule(path, null, p.name);
            const input = this.valueField(`sysparam-${p.name}`, `${p.name} value`, p.value, refused, rule !== null);
            const commit = () => {
                const value = input.value.trim();
                if (value === p.value) { if (refused) { this.refused.delete(key); this.render(); } return; }
                const notFinite = notFiniteError(p.name, p.type, value);
                if (notFinite) { this.refuse(key, notFinite); return; }
                this.run(this.store.execute(new SetSystemParameter(path, { ...p, value })).then(() => { this.refused.delete(key); this.render(); }),
                    (message) => this.refuse(key, message));
            };
            if (rule) {
                input.addEventListener('keydown', (e) => { if (e.key === 'Enter') commit(); });
                input.addEventListener('change', commit);
            }
            return h('tr', { 'data-sysparam': p.name, class: this.rowClass(rule !== null), title: p.description },
                h('th', {}, p.name),
                h('td', {}, input, this.boundsNote(rule), refused ? h('div', { class: 'field-error', role: 'alert' }, refused) : null),
                h('td', { class: 'unit' }, p.unit));
        });
        const newName = h('input', { name: 'new-sysparam-name', placeholder: 'name', 'aria-label': 'New parameter name' });
        const newValue = h('input', { name: 'new-sysparam-value', placeholder: 'value', 'aria-label': 'New parameter value' });
        const newUnit = h('input', { name: 'new-sysparam-unit', placeholder: 'unit', 'aria-label': 'New parameter unit' });
        const addError = this.refused.get('$new');
        const add = h('form', {
            class: 'sysparam-add',
            onsubmit: (e: Event) => {
                e.preventDefault();
                const name = newName.value.trim();
                if (!name) return;
                const param = { name, value: newValue.value.trim() || '0', type: 'double' as const, unit: newUnit.value.trim(), description: '' };
                const notFinite = notFiniteError(name, param.type, param.value);
                if (notFinite) { this.refuse('$new', notFinite); return; }
                this.run(this.store.execute(new SetSystemParameter(path, param)).then(() => { this.refused.delete('$new'); this.render(); }),
                    (message) => this.refuse('$new', message));
            },
        }, newName, newValue, newUnit, h('button', { type: 'submit' }, 'Add'));
        return [
            h('h2', {}, path.length ? `Subsystem ${system.name}` : `Model ${system.name}`),
            h('p', { class: 'muted' }, `${system.components.length} components, ${system.connections.length} connections`),
            h('h3', {}, 'System parameters'),
            rows.length ? h('table', { class: 'param-table' }, h('tbody', {}, ...rows)) : h('p', { class: 'muted' }, 'None.'),
            this.permissions.allows('system-parameters') ? add : h('span'),
            addError ? h('div', { class: 'field-error', role: 'alert' }, addError) : h('span'),
            h('p', { class: 'muted hint' }, 'Parameter values accept numbers, expressions and system parameter names.'),
        ];
    }

    private may(edit: StructuralEdit): boolean {
        return this.permissions.allows(edit);
    }

    /** Shows why a value was refused; the field goes back to the model's value (drawn anew even if the reason is the same). */
    private refuse(key: string, message: string): void {
        this.refused.set(key, message);
        this.signature = '';
        this.render();
    }

    /** A parameter's value field: read-only unless it may change, marked while its last value was refused. */
    private valueField(name: string, label: string, value: string, refused: string | undefined, editable: boolean): HTMLInputElement {
        return h('input', {
            name, value, 'aria-label': label, readonly: !editable, class: refused ? 'invalid' : '',
            'aria-invalid': refused ? 'true' : 'false',
            title: editable ? undefined : 'Locked: this assignment does not let you change it',
        });
    }

    /** In a locked copy the parameters that may change stand out from the read-only ones. */
    private rowClass(editable: boolean): string {
        if (!this.permissions.locked) return '';
        return editable ? 'param-allowed' : 'param-locked';
    }

    /** The allowed range beside a field of a locked copy. */
    private boundsNote(rule: ReturnType<EditPermissions['parameterRule']>): HTMLElement | null {
        if (!this.permissions.locked || !rule) return null;
        const bounds = boundsText(rule);
        return h('span', { class: 'param-bounds', 'data-testid': 'param-bounds' }, bounds ? `allowed: ${bounds}` : 'allowed: any value');
    }
}
