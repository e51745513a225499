// Variables of each node type, in storage order, as the core logs them (core/NodeTypes.cpp).
// They name the logged results: Component#Port#Variable.
export interface NodeVariable { name: string; unit: string }

const v = (name: string, unit: string): NodeVariable => ({ name, unit });

export const nodeVariables: Record<string, NodeVariable[]> = {
    NodeHydraulic: [v('Flow', 'm^3/s'), v('Pressure', 'Pa'), v('Temperature', 'K'), v('WaveVariable', 'Pa'),
        v('CharImpedance', 'Pa s/m^3'), v('HeatFlow', '?')],
    NodeMechanic: [v('Velocity', 'm/s'), v('Force', 'N'), v('Position', 'm'), v('WaveVariable', 'N'),
        v('CharImpedance', 'N s/m'), v('EquivalentMass', 'kg')],
    NodeMechanicRotational: [v('AngularVelocity', 'rad/s'), v('Torque', 'Nm'), v('Angle', 'rad'),
        v('WaveVariable', 'Nm'), v('CharImpedance', '?'), v('EquivalentInertia', 'kg m^2')],
    NodeElectric: [v('Voltage', 'V'), v('Current', 'A'), v('WaveVariable', 'V'), v('CharImpedance', 'V/A')],
    NodeSignal: [v('Value', '')],
    NodePneumatic: [v('EnergyFlow', 'J/s'), v('Pressure', 'Pa'), v('WaveVariable', 'Pa'), v('CharImpedance', 's/m^3'),
        v('MassFlow', 'kg/s'), v('Density', 'kg/m^3'), v('DensityWaveVariable', 'kg/m^3'),
        v('DensityCharImpedance', 's/m^3'), v('Temperature', 'K')],
    NodePetriNet: [v('State', ''), v('Flow', '')],
};

/** The variables worth plotting first: intensity and flow (not the TLM internals). */
export const primaryVariables = new Set(['Pressure', 'Flow', 'Position', 'Velocity', 'Force', 'Angle',
    'AngularVelocity', 'Torque', 'Voltage', 'Current', 'Value', 'MassFlow', 'Temperature', 'State']);

/** Colour of a node type in the editor and the plots. */
export function nodeColour(nodeType: string | null | undefined): string {
    switch (nodeType) {
    case 'NodeHydraulic': return '#1f6fd1';
    case 'NodeMechanic': return '#2e8b3d';
    case 'NodeMechanicRotational': return '#6b8e23';
    case 'NodeElectric': return '#d17a00';
    case 'NodePneumatic': return '#0f9a9a';
    case 'NodePetriNet': return '#8a4fbf';
    case 'NodeSignal': return '#3c3c3c';
    default: return '#888888';
    }
}
