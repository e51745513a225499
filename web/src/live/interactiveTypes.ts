// Hopsan's interactive component types (../shared/reference/animation.json, facts only): in
// its animation mode the user drags a valve's spool or a slider (adjustable) or clicks a
// switch (switchable) to set one of the component's inputs. In live mode these types get such
// a control by default. Adjustable: value = dragged icon pixels × gain, so its range is the
// drag range times the gain. A unit test checks this table against animation.json.

export type Interaction =
    | { kind: 'adjustable'; port: string; dataname: string; min: number; max: number; gain: number }
    | { kind: 'switchable'; port: string; dataname: string; off: number; on: number };

const VALVE_SPOOL = (min: number, max: number, gain = 0.00025): Interaction => ({ kind: 'adjustable', port: 'in', dataname: 'Value', min, max, gain });
const VALVE_SWITCH: Interaction = { kind: 'switchable', port: 'in', dataname: 'Value', off: 0, on: 1 };

export const INTERACTIVE_TYPES: Readonly<Record<string, Interaction>> = {
    ElectricSwitch: { kind: 'switchable', port: 'state', dataname: 'Value', off: 0, on: 1 },
    Hydraulic22DirectionalCheckValve: VALVE_SWITCH,
    Hydraulic22DirectionalValve: VALVE_SWITCH,
    Hydraulic32DirectionalValve: VALVE_SWITCH,
    Hydraulic42DirectionalValve: VALVE_SWITCH,
    Hydraulic22Valve: VALVE_SPOOL(0, 40),
    Hydraulic33Valve: VALVE_SPOOL(-40, 40),
    Hydraulic42Valve: VALVE_SPOOL(0, 40),
    Hydraulic42Valve2: VALVE_SPOOL(-40, 0, -0.00025),
    Hydraulic43LoadSensingValve: VALVE_SPOOL(-40, 40),
    Hydraulic43Valve: VALVE_SPOOL(-40, 40),
    Hydraulic43ValveNeutralSupplyToTank: VALVE_SPOOL(-40, 40),
    Hydraulic43ValveNeutralToTank: VALVE_SPOOL(-40, 40),
    HydraulicOpenCenterValve: VALVE_SPOOL(-60, 60),
    SignalAnimationSwitch: { kind: 'switchable', port: 'out', dataname: 'Value', off: 0, on: 1 },
    // dragged upwards: Hopsan's y gain and range
    SignalAnimationSlider: { kind: 'adjustable', port: 'in', dataname: 'Value', min: 0, max: 97, gain: 0.010309278 },
};
