// An FMU interface as the export dialog shows it: signal inputs and outputs, power ports with
// the FMU variables that carry their TLM variables, parameters and the step.
import type { FmuInterface, FmuPowerPort, FmuVariable } from '../protocol/types';

export const STEP_VARIABLE = 'tlmhub.timestep';

export interface PortVariable { nodeVariable: string; direction: 'in' | 'out'; variable: FmuVariable | undefined }
export interface PowerPortView { port: FmuPowerPort; variables: PortVariable[] }

export interface InterfaceView {
    inputs: FmuVariable[];        // from SignalInputInterface components
    outputs: FmuVariable[];       // from SignalOutputInterface components
    powerPorts: PowerPortView[];
    parameters: FmuVariable[];    // system parameters and the component parameters asked for
    step: FmuVariable | undefined;
}

export function interfaceView(iface: FmuInterface): InterfaceView {
    const byName = new Map(iface.variables.map((v) => [v.name, v]));
    // power port variables are inputs and outputs too: listed under their port only
    const ofPorts = new Set(iface.power_ports.flatMap((p) => [...p.inputs, ...p.outputs].map((v) => v.variable)));
    const signal = (causality: FmuVariable['causality']) =>
        iface.variables.filter((v) => v.causality === causality && !ofPorts.has(v.name));
    return {
        inputs: signal('input'),
        outputs: signal('output'),
        powerPorts: iface.power_ports.map((port) => ({
            port,
            variables: [
                ...port.inputs.map((v) => ({ nodeVariable: v.node_variable, direction: 'in' as const, variable: byName.get(v.variable) })),
                ...port.outputs.map((v) => ({ nodeVariable: v.node_variable, direction: 'out' as const, variable: byName.get(v.variable) })),
            ],
        })),
        parameters: iface.variables.filter((v) => v.causality === 'parameter' && v.name !== STEP_VARIABLE),
        step: byName.get(STEP_VARIABLE),
    };
}

/** Whether the model has interface components: without them the FMU has no inputs or outputs. */
export function hasInterfaceComponents(view: InterfaceView): boolean {
    return view.inputs.length > 0 || view.outputs.length > 0 || view.powerPorts.length > 0;
}

/** "Gain.k, Mass.m" or one per line -> ["Gain.k", "Mass.m"]. */
export function parameterList(text: string): string[] {
    return text.split(/[\s,]+/).filter((p) => p !== '');
}
