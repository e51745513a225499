// @vitest-environment jsdom
import { describe, expect, it } from 'vitest';
import extract from '../model/appearance.generated.json';
import { componentIcon, fittedHalfSize, iconFamily, type Family } from './icons';

const types = (extract as unknown as { types: Record<string, { width: number; height: number }> }).types;

/** Representative types of each family, from Hopsan's library (appearance.generated.json). */
const expected: Record<Family, string[]> = {
    'directional-valve': ['Hydraulic43Valve', 'Hydraulic22DirectionalValve', 'Hydraulic42DirectionalValve', 'Hydraulic22DirectionalCheckValve', 'HydraulicPressureControlled42Valve', 'HydraulicValve43', 'HydraulicOpenCenterValve'],
    'pressure-valve': ['HydraulicPressureReliefValve', 'HydraulicPressureReducingValve', 'HydraulicPressureCompensatingValve', 'HydraulicPressureControlValveG', 'HydraulicCounterBalanceValveG', 'HydraulicOverCenterValve'],
    'check-valve': ['HydraulicCheckValve', 'HydraulicCheckValvePreLoaded', 'HydraulicPilotControlledCheckValve', 'HydraulicCheckValveWithOrifice', 'Hydraulic22PoppetValve'],
    'shuttle-valve': ['HydraulicShuttleValve'],
    pump: ['HydraulicFixedDisplacementPump', 'HydraulicVariableDisplacementPump', 'HydraulicPressureControlledPump', 'HydraulicCentrifugalPump'],
    motor: ['HydraulicFixedDisplacementMotorQ', 'HydraulicVariableDisplacementMotorQ', 'HydraulicMachineC', 'HydraulicMotorJload', 'PneumaticMachine'],
    cylinder: ['HydraulicCylinderC', 'HydraulicCylinderQ', 'HydraulicSymmetricCylinderC', 'HydraulicSpringLoadedPistonC', 'HydraulicPistonMload', 'HydraulicPumpPiston'],
    accumulator: ['HydraulicAckumulator', 'HydraulicPistonAckumulator'],
    volume: ['HydraulicVolume', 'HydraulicVolumeMultiPort', 'HydraulicHose', 'PneumaticVolume2'],
    line: ['HydraulicTLMlossless', 'HydraulicLosslessConnector', 'HydraulicLosslessTConnector', 'MechanicTranslationalLosslessConnector'],
    orifice: ['HydraulicLaminarOrifice', 'HydraulicTurbulentOrifice', 'HydraulicOrificeG', 'PneumaticOrifice'],
    tank: ['HydraulicTankC', 'HydraulicMultiTankC', 'HydraulicFuelTankG'],
    plug: ['HydraulicPlugQ'],
    'fluid-source': ['HydraulicPressureSourceC', 'HydraulicPressureSourceQ', 'HydraulicFlowSourceQ', 'HydraulicMultiPressureSourceC', 'PneumaticPTsrc', 'PneumaticQsrc'],
    sensor: ['HydraulicPressureSensor', 'HydraulicFlowSensor', 'HydraulicDifferentialPressureSensor', 'MechanicPositionSensor', 'MechanicSpeedSensor', 'MechanicForceSensor',
        'MechanicAngleSensor', 'MechanicAngularVelocitySensor', 'MechanicTorqueSensor', 'ElectricUsensor', 'ElectricIsensor', 'PneumaticPsensor'],
    mass: ['MechanicTranslationalMass', 'MechanicTranslationalMassWithCoulombFriction', 'MechanicM2load1D', 'MechanicMkcload1D', 'MechanicTranslationalMassWithLever'],
    spring: ['MechanicTranslationalSpring', 'MechanicSpring', 'MechanicTranslationalSpringWithSlack'],
    damper: [],
    fixed: ['MechanicFixedPosition', 'MechanicFixedPositionMultiPort', 'MechanicFreeLengthWall'],
    inertia: ['MechanicRotationalInertia', 'MechanicRotationalInertiaWithCoulombFriction', 'MechanicRotationalInertiaWithGearRatio'],
    'torsion-spring': ['MechanicTorsionalSpring', 'MechanicRotShaft', 'MechanicRotShaftG'],
    gear: ['MechanicGear', 'MechanicGearShaft', 'MechanicRackAndPinion', 'MechanicWormDrive'],
    pulley: ['MechanicPulley'],
    lever: ['MechanicJLink'],
    'mechanic-source': ['MechanicForceTransformer', 'MechanicVelocityTransformer', 'MechanicTorqueTransformer', 'MechanicThetaSource'],
    resistor: ['ElectricResistor', 'ElectricVarResistor'],
    capacitor: ['ElectricCapacitance2', 'ElectricCapacitanceMultiPort'],
    inductor: ['ElectricInductance', 'ElectricInductanceC'],
    'voltage-source': ['ElectricUsource', 'ElectricVoltageSourceQ', 'ElectricVoltageSourceMultiPortC'],
    'current-source': ['ElectricIsource'],
    battery: ['ElectricBattery'],
    'electric-ground': ['ElectricGround', 'ElectricVoltageSourceQ|Ground'],
    'electric-motor': ['ElectricMotor', 'ElectricMotorGear', 'MechanicMotor'],
    switch: ['ElectricSwitch'],
    'boundary-source': ['HydraulicCSource', 'HydraulicQSource', 'ElectricCSource', 'MechanicTranslationalQSource'],
    gain: ['SignalGain'],
    sum: ['SignalAdd', 'SignalSubtract', 'SignalSum', 'SignalSub'],
    product: ['SignalMultiply', 'SignalDivide'],
    integrator: ['SignalIntegrator2'],
    delay: ['SignalUnitDelay', 'SignalTimeDelay', 'SignalVariableTimeDelay'],
    'transfer-function': ['SignalFirstOrderTransferFunction', 'SignalSecondOrderTransferFunction', 'SignalFirstOrderFilter', 'SignalSecondOrderFilter'],
    filter: ['SignalLP1Filter', 'SignalLP2Filter', 'SignalHP1Filter', 'SignalHP2Filter'],
    step: ['SignalStep', 'SignalSoftStep', 'SignalStepExponentialDelay'],
    sine: ['SignalSineWave'],
    ramp: ['SignalRamp'],
    constant: ['SignalConstant'],
    pulse: ['SignalPulse'],
    square: ['SignalSquareWave', 'SignalPulseWave'],
    noise: ['SignalNoiseGenerator', 'SignalAdditiveNoise'],
    staircase: ['SignalStaircase'],
    clock: ['SignalTime', 'SignalTimestep'],
    sink: ['SignalSink', 'SignalLogger'],
    and: ['SignalAnd'], or: ['SignalOr'], not: ['SignalNot'], xor: ['SignalXor'],
    comparator: ['SignalGreaterThan', 'SignalSmallerThan'],
    latch: ['SignalSRlatch', 'SignalJKlatch'],
    saturation: ['SignalSaturation'],
    characteristic: ['SignalDeadZone', 'SignalHysteresis', 'SignalRateLimiter', 'SignalSign', 'SignalAbsoluteValue'],
    'lookup-table': ['Signal1DLookupTable', 'Signal2DLookupTable', 'SignalLookUpTable2D'],
    'math-function': ['SignalSin', 'SignalExp', 'SignalSqrt', 'SignalSquare', 'SignalMin', 'SignalFloor'],
    pid: ['SignalPID', 'SignalPID2', 'SignalPIlead'],
    'attitude-control': ['SignalAttitudeControl', 'SignalAttitudeTVCcontrol'],
    'current-controller': ['ElectricIcontroller'],
    pwm: ['ElectricPWMdceq'],
    'functional-flow': ['SignalFFB', 'SignalFFBand', 'SignalFFBandIn', 'SignalFFBloop', 'SignalFFBloopIn', 'SignalFFBor', 'SignalFFBorIn'],
    router: ['SignalDualRoute', 'SignalTripleRoute', 'SignalQuadRoute'],
    counter: ['SignalCounter'],
    'steady-state': ['SignalSteadyStateIdentifier'],
    stop: ['SignalStopSimulation'],
    globe: ['SignalEarthCoordinates'],
    waypoint: ['SignalWaypoint'],
    'state-monitor': ['SignalStateMonitor'],
    'time-accelerator': ['SignalTimeAccelerator'],
    'dial-gauge': ['SignalAnimationGauge'],
    lamp: ['SignalAnimationLamp'],
    slider: ['SignalAnimationSlider'],
    toggle: ['SignalAnimationSwitch', 'SignalAnimationSwitch|SignalAnimationMomentarySwitch'],
    display: ['SignalDisplay'],
    'numeric-input': ['SignalNumericalInput'],
    'signal-bus': ['Signal2DRead', 'Signal2DReadWrite', 'Signal2DSplit', 'Signal2DWrite', 'Signal2DWriteRead'],
    'circular-segment': ['SignalSegare', 'SignalDxSegare'],
    activity: ['ActivityDiagramAction', 'ActivityDiagramDecision', 'ActivityDiagramFork', 'ActivityDiagramJoin0', 'ActivityDiagramFinalNode', 'ActivityDiagramEdge'],
    aircraft: ['AeroAircraft6DOFS', 'AeroAircraft6DOFSS'],
    rocket: ['AeroVehicleTVC'],
    'jet-engine': ['AeroJetEngine'],
    propeller: ['AeroPropeller'],
    'aero-fuel-tank': ['AeroFuelTank'],
    'combustion-chamber': ['AeroCombustionChamberMono'],
    atmosphere: ['AeroAtmosphere'],
    wind: ['AeroWind'],
    'flight-recorder': ['AeroFlightRecorder'],
    vehicle: ['MechanicVehicle1D'],
    engine: ['CombustionEngine'],
    'fork-lift': ['Forks'],
    'valve-plate': ['HydraulicValvePlate'],
    'swash-plate': ['MechanicSwashPlate', 'MechanicCylinderBlockWithSwashPlate'],
    interface: ['HydraulicInterfaceC', 'MechanicRotationalInterfaceTLM', 'ElectricInterfaceQ', 'PetriNetInterfaceC', 'SignalInputInterface', 'SignalOutputInterface'],
    fmu: ['FMIWrapper', 'FMIWrapperQ'],
    script: ['SignalNumHopSISO'],
    'pass-through': ['HydraulicDummyC', 'HydraulicDummyQ', 'SignalDummy'],
    contours: ['OptimizationTestFunction2D', 'OptimizationTestFunction6D'],
    'system-port': ['HopsanGUISystemPort'],
};

/**
 * Words of Hopsan type names that belong to a family: every type with one of them must get a
 * drawn symbol, not the labelled box (independent of the rules in families.ts, on purpose).
 */
const familyWords = /Valve|Pump|Motor|Cylinder|Piston|Ackumulator|Volume|Hose|Orifice|Tank|Sensor|sensor|Source|Mass|Spring|Inertia|FixedPosition|Gear|Resistor|Capacit|Inductance|Battery|Ground|Switch|^Signal(Gain|Add|Sub|Subtract|Sum|Multiply|Divide|Integrator2|Step|SineWave|Ramp|Constant|Pulse|SquareWave|Sink|And|Or|Not|Xor|GreaterThan|SmallerThan|Saturation|UnitDelay|TimeDelay)$|TransferFunction|LookupTable|Filter$/;
/** Family words in names of parts that are no such component (a pump's valve plate, a swash plate's cylinder block). */
const notAFamily = /ValvePlate|CylinderBlock|Interface|Dummy|^Aero|Animation/;

interface Box { x0: number; y0: number; x1: number; y1: number }

/** The extent of every drawn element (text by an estimate of its glyphs' size). */
function extents(g: SVGGElement): { el: Element; box: Box }[] {
    const num = (e: Element, k: string) => Number(e.getAttribute(k) ?? 0);
    const out: { el: Element; box: Box }[] = [];
    for (const e of [...g.children].filter((c) => !/icon-frame|icon-inner/.test(c.getAttribute('class') ?? ''))) {
        let pts: number[][] = [];
        const tag = e.tagName.toLowerCase();
        if (tag === 'polyline' || tag === 'polygon') pts = e.getAttribute('points')!.trim().split(/\s+/).map((p) => p.split(',').map(Number));
        else if (tag === 'rect') pts = [[num(e, 'x'), num(e, 'y')], [num(e, 'x') + num(e, 'width'), num(e, 'y') + num(e, 'height')]];
        else if (tag === 'circle') pts = [[num(e, 'cx') - num(e, 'r'), num(e, 'cy') - num(e, 'r')], [num(e, 'cx') + num(e, 'r'), num(e, 'cy') + num(e, 'r')]];
        else if (tag === 'text') {
            const [size, len] = [num(e, 'font-size'), [...(e.textContent ?? '')].length];
            pts = [[num(e, 'x') - size * 0.3 * len, num(e, 'y') - size * 0.45], [num(e, 'x') + size * 0.3 * len, num(e, 'y') + size * 0.45]];
        } else throw new Error(`${tag}: an element the bounds check cannot measure`);
        for (const p of pts) expect(p.every(Number.isFinite), `${tag} ${e.outerHTML}`).toBe(true);
        out.push({ el: e, box: { x0: Math.min(...pts.map((p) => p[0])), y0: Math.min(...pts.map((p) => p[1])), x1: Math.max(...pts.map((p) => p[0])), y1: Math.max(...pts.map((p) => p[1])) } });
    }
    return out;
}

describe('component icons', () => {
    it('choose the family expected for representative Hopsan types', () => {
        for (const [family, names] of Object.entries(expected)) {
            for (const name of names) {
                expect(types[name], `${name} is a Hopsan type`).toBeTruthy();
                expect(iconFamily(name), name).toBe(family);
            }
        }
        for (const other of ['Subsystem', 'ConditionalSubsystem', 'NoSuchType']) expect(iconFamily(other), other).toBeNull();
    });

    it('draw a symbol, not the labelled box, for every Hopsan type named like a family', () => {
        const named = Object.keys(types).filter((t) => familyWords.test(t) && !notAFamily.test(t));
        expect(named.length).toBeGreaterThan(150);
        for (const type of named) {
            const { width, height } = types[type];
            const g = componentIcon(type, width / 2, height / 2);
            expect(g.querySelector('.icon-fallback'), type).toBeNull();
            expect(extents(g).length, type).toBeGreaterThan(0);
        }
        expect(componentIcon('MyOwnJetEngine', 100, 26).querySelector('.icon-fallback')?.textContent).toBe('MOJE');
    });

    it('keep every glyph inside its box, at Hopsan sizes and at the palette size', () => {
        for (const [type, { width, height }] of Object.entries(types)) {
            for (const [w, h] of [[width / 2, height / 2], [10, 8], fittedHalfSize(type, 10, 8)]) {
                for (const { el, box } of extents(componentIcon(type, w, h))) {
                    const where = `${type} at ${w}x${h}: ${el.outerHTML.slice(0, 120)}`;
                    expect(box.x0, where).toBeGreaterThanOrEqual(-w - 0.01);
                    expect(box.x1, where).toBeLessThanOrEqual(w + 0.01);
                    expect(box.y0, where).toBeGreaterThanOrEqual(-h - 0.01);
                    expect(box.y1, where).toBeLessThanOrEqual(h + 0.01);
                }
            }
        }
    });

    it('fit small icons at the aspect of their type', () => {
        expect(fittedHalfSize('HydraulicFixedDisplacementPump', 10, 8)).toEqual([7.2, 8]);
        expect(fittedHalfSize('HydraulicCylinderC', 10, 8)).toEqual([10, 4]);
        expect(fittedHalfSize('NoSuchType', 10, 8)).toEqual([10, 8]);
    });

    it('keep cylinders see-through with a solid barrel, pumps and motors apart by their triangle', () => {
        const cyl = componentIcon('HydraulicCylinderC', 59.5, 20);
        expect(cyl.classList.contains('icon-open')).toBe(true);
        expect(cyl.querySelectorAll('.icon-solid').length).toBe(1);
        expect(componentIcon('HydraulicPiston', 59.5, 20).classList.contains('icon-open')).toBe(false);
        const pump = componentIcon('HydraulicFixedDisplacementPump', 45, 50);
        const motor = componentIcon('HydraulicFixedDisplacementMotorQ', 45, 50);
        expect([pump.querySelectorAll('.glyph-pump-triangle').length, pump.querySelectorAll('.glyph-motor-triangle').length]).toEqual([1, 0]);
        expect([motor.querySelectorAll('.glyph-pump-triangle').length, motor.querySelectorAll('.glyph-motor-triangle').length]).toEqual([0, 1]);
        expect(pump.querySelectorAll('.glyph-variable').length).toBe(0);
        expect(componentIcon('HydraulicVariableDisplacementPump', 52, 50).querySelectorAll('.glyph-variable').length).toBe(2);
        // a sensor's pointer, no source triangle; a source's triangle, no pointer
        const [gauge, src] = [componentIcon('HydraulicPressureSensor', 18, 18), componentIcon('HydraulicPressureSourceC', 12, 12)];
        expect([gauge.querySelectorAll('.glyph-pointer').length, gauge.querySelectorAll('.glyph-source-triangle').length]).toEqual([2, 0]);
        expect([src.querySelectorAll('.glyph-pointer').length, src.querySelectorAll('.glyph-source-triangle').length]).toEqual([0, 1]);
    });
});
