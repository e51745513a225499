// The FMU interface as tables: what the export dialog shows before the download.
import { h } from '../ui/dom';
import type { FmuInterface, FmuVariable } from '../protocol/types';
import { hasInterfaceComponents, interfaceView, STEP_VARIABLE, type PowerPortView } from './fmuInterface';

export const NO_INTERFACE_HINT = 'This model has no interface components, so its FMU has no inputs or outputs. '
    + 'Add SignalInputInterface / SignalOutputInterface components for signals, or <Domain>InterfaceC / <Domain>InterfaceQ '
    + 'components (e.g. HydraulicInterfaceC, MechanicInterfaceQ) for power ports, at the top level of the model.';

function number(value: number | null | undefined): string {
    return value === null || value === undefined ? '' : String(value);
}

function section(testId: string, title: string, count: number, body: Node): HTMLElement {
    return h('section', { class: 'fmu-section', 'data-testid': testId },
        h('h3', {}, `${title} `, h('span', { class: 'muted' }, `(${count})`)), body);
}

function variableTable(variables: FmuVariable[], empty: string): Node {
    if (variables.length === 0) return h('p', { class: 'muted' }, empty);
    return h('table', { class: 'fmu-table' },
        h('thead', {}, h('tr', {}, h('th', {}, 'Name'), h('th', {}, 'Ref'), h('th', {}, 'Start'), h('th', {}, 'Unit'), h('th', {}, 'Description'))),
        h('tbody', {}, ...variables.map((v) => h('tr', { 'data-variable': v.name },
            h('td', { class: 'fmu-name' }, v.name), h('td', {}, v.value_reference), h('td', {}, number(v.start)),
            h('td', {}, v.unit), h('td', { class: 'muted' }, v.description)))));
}

function powerPortTable(ports: PowerPortView[]): Node {
    if (ports.length === 0) return h('p', { class: 'muted' }, 'None.');
    return h('table', { class: 'fmu-table' },
        h('thead', {}, h('tr', {}, h('th', {}, 'Port'), h('th', {}, ''), h('th', {}, 'Variable'), h('th', {}, 'Ref'), h('th', {}, 'Unit'), h('th', {}, 'Description'))),
        h('tbody', {}, ...ports.flatMap(({ port, variables }) => [
            h('tr', { class: 'fmu-port', 'data-port': port.name },
                h('td', { colspan: 6 }, h('strong', {}, port.name), ' ',
                    h('span', { class: 'muted' }, `${port.node_type}, ${port.kind}-type: takes ${port.inputs.map((v) => v.node_variable).join(', ')}, gives ${port.outputs.map((v) => v.node_variable).join(', ')}`))),
            ...variables.map(({ direction, variable, nodeVariable }) => h('tr', { 'data-variable': variable?.name ?? nodeVariable },
                h('td', {}, ''), h('td', { class: 'fmu-direction', title: direction === 'in' ? 'input of the FMU' : 'output of the FMU' }, direction === 'in' ? '→ in' : 'out →'),
                h('td', { class: 'fmu-name' }, variable?.name ?? nodeVariable), h('td', {}, variable?.value_reference ?? ''),
                h('td', {}, variable?.unit ?? ''), h('td', { class: 'muted' }, variable?.description ?? ''))),
        ])));
}

export function renderFmuInterface(iface: FmuInterface): HTMLElement {
    const view = interfaceView(iface);
    const experiment = iface.default_experiment;
    return h('div', { class: 'fmu-interface' },
        h('p', { class: 'fmu-summary' },
            h('strong', { 'data-testid': 'fmu-file' }, `${iface.model_identifier}.fmu`),
            ' · FMI 2.0 co-simulation, linux64 · step ',
            h('span', { 'data-testid': 'fmu-step' }, `${number(view.step?.start)} s`),
            h('span', { class: 'muted' }, ` (parameter ${STEP_VARIABLE}), default experiment ${number(experiment.start_time)} – ${number(experiment.stop_time)} s`)),
        hasInterfaceComponents(view) ? '' : h('p', { class: 'fmu-hint', role: 'note', 'data-testid': 'fmu-hint' }, NO_INTERFACE_HINT),
        section('fmu-inputs', 'Inputs', view.inputs.length, variableTable(view.inputs, 'None.')),
        section('fmu-outputs', 'Outputs', view.outputs.length, variableTable(view.outputs, 'None.')),
        section('fmu-power-ports', 'Power ports', view.powerPorts.length, powerPortTable(view.powerPorts)),
        section('fmu-parameters', 'Parameters', view.parameters.length,
            variableTable(view.parameters, 'None: add component parameters below.')));
}
