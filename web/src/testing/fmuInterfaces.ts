// FMU interfaces for the export dialog's tests: the one tests/server/data/FmuGain.hmf has
// (shortened to one power port), with Gain.k offered as a parameter.
import type { FmuInterface, FmuVariable } from '../protocol/types';

function variable(name: string, value_reference: number, causality: FmuVariable['causality'], start: number | null = null): FmuVariable {
    return { name, value_reference, causality, variability: causality === 'parameter' ? 'fixed' : 'continuous', type: 'Real', unit: '', description: '', start };
}

export const gainInterface: FmuInterface = {
    model_identifier: 'FmuGain', model_name: 'FmuGain',
    default_experiment: { start_time: 0, stop_time: 2, step_size: 0.001 },
    variables: [
        variable('PA.c', 0, 'input', 0), variable('PA.Zc', 1, 'input', 0), variable('u', 2, 'input', 0),
        variable('PA.p', 3, 'output'), variable('PA.q', 4, 'output'), variable('y', 5, 'output'),
        variable('Gain.k', 6, 'parameter', 3), variable('tlmhub.timestep', 7, 'parameter', 0.001),
    ],
    power_ports: [{
        name: 'PA', node_type: 'NodeHydraulic', kind: 'C',
        inputs: [{ node_variable: 'c', variable: 'PA.c' }, { node_variable: 'Zc', variable: 'PA.Zc' }],
        outputs: [{ node_variable: 'p', variable: 'PA.p' }, { node_variable: 'q', variable: 'PA.q' }],
    }],
};
