// Which symbol family a component type belongs to, from its Hopsan type name. The rules are
// tried in order: the first match wins, so narrower names (a check valve inside a directional
// valve's name, a pump piston) come before the broad ones.

export type Family =
    // fluid power (ISO 1219)
    | 'directional-valve' | 'pressure-valve' | 'check-valve' | 'shuttle-valve' | 'pump' | 'motor'
    | 'cylinder' | 'accumulator' | 'volume' | 'line' | 'orifice' | 'tank' | 'plug' | 'fluid-source'
    // sensors of every domain: a gauge
    | 'sensor'
    // mechanics
    | 'mass' | 'spring' | 'damper' | 'fixed' | 'inertia' | 'torsion-spring' | 'gear' | 'pulley' | 'lever' | 'mechanic-source'
    // electrics
    | 'resistor' | 'capacitor' | 'inductor' | 'voltage-source' | 'current-source' | 'battery' | 'electric-ground'
    | 'electric-motor' | 'switch' | 'boundary-source'
    // signals (block diagrams)
    | 'gain' | 'sum' | 'product' | 'integrator' | 'delay' | 'transfer-function' | 'filter'
    | 'step' | 'sine' | 'ramp' | 'constant' | 'pulse' | 'square' | 'noise' | 'staircase' | 'clock' | 'sink'
    | 'and' | 'or' | 'not' | 'xor' | 'comparator' | 'latch' | 'saturation' | 'characteristic' | 'lookup-table' | 'math-function'
    // controllers, flow logic, navigation and widgets
    | 'pid' | 'attitude-control' | 'current-controller' | 'pwm' | 'functional-flow' | 'router' | 'counter' | 'steady-state' | 'stop'
    | 'globe' | 'waypoint' | 'state-monitor' | 'time-accelerator' | 'dial-gauge' | 'lamp' | 'slider' | 'toggle' | 'display' | 'numeric-input'
    | 'signal-bus' | 'circular-segment' | 'activity'
    // aircraft, vehicles and machines
    | 'aircraft' | 'rocket' | 'jet-engine' | 'propeller' | 'aero-fuel-tank' | 'combustion-chamber' | 'atmosphere' | 'wind' | 'flight-recorder'
    | 'vehicle' | 'engine' | 'fork-lift' | 'valve-plate' | 'swash-plate'
    // links to other tools, scripts, benchmarks and test functions
    | 'interface' | 'fmu' | 'script' | 'pass-through' | 'contours' | 'system-port';

const rules: [Family | null, RegExp][] = [
    // links, benchmarks and machine parts first: their names hold words of the families below
    ['interface', /Interface/],
    ['fmu', /^FMIWrapper/],
    ['pass-through', /Dummy/],
    ['valve-plate', /ValvePlate/],
    ['swash-plate', /SwashPlate/],
    ['system-port', /^HopsanGUISystemPort$/],
    // aircraft and vehicles
    ['aircraft', /^AeroAircraft/],
    ['rocket', /^AeroVehicleTVC$/],
    ['jet-engine', /^AeroJetEngine$/],
    ['propeller', /^AeroPropeller$/],
    ['aero-fuel-tank', /^AeroFuelTank$/],
    ['combustion-chamber', /^AeroCombustionChamber/],
    ['atmosphere', /^AeroAtmosphere$/],
    ['wind', /^AeroWind$/],
    ['flight-recorder', /^AeroFlightRecorder$/],
    ['vehicle', /Vehicle1D$/],
    ['engine', /^CombustionEngine$/],
    ['fork-lift', /^Forks$/],
    ['contours', /^OptimizationTestFunction/],
    // controllers, flow logic, navigation, widgets
    ['pid', /^SignalPI(D\d?|lead)$/],
    ['attitude-control', /^SignalAttitude(TVC)?[Cc]ontrol$/],
    ['current-controller', /^ElectricIcontroller$/],
    ['pwm', /^ElectricPWM/],
    ['activity', /^ActivityDiagram/],
    ['functional-flow', /^SignalFFB/],
    ['router', /^Signal(Dual|Triple|Quad)Route$/],
    ['counter', /^SignalCounter$/],
    ['steady-state', /^SignalSteadyStateIdentifier$/],
    ['stop', /^SignalStopSimulation$/],
    ['globe', /^SignalEarthCoordinates$/],
    ['waypoint', /^SignalWaypoint$/],
    ['state-monitor', /^SignalStateMonitor$/],
    ['time-accelerator', /^SignalTimeAccelerator$/],
    ['dial-gauge', /^SignalAnimationGauge$/],
    ['lamp', /^SignalAnimationLamp$/],
    ['slider', /^SignalAnimationSlider$/],
    ['toggle', /^SignalAnimation(Momentary)?Switch/],
    ['display', /^SignalDisplay$/],
    ['numeric-input', /^SignalNumericalInput$/],
    ['signal-bus', /^Signal2D(Read|Write|Split)/],
    ['circular-segment', /Segare$/],
    ['script', /^SignalNumHop/],
    // valves
    ['directional-valve', /^Hydraulic\d\dDirectional/],
    ['shuttle-valve', /ShuttleValve/],
    ['check-valve', /CheckValve|PoppetValve/],
    ['pressure-valve', /Pressure(Relief|Reducing|Compensating|Drop)|PressureControl(led)?Valve|CounterBalance|OverCenter/],
    ['directional-valve', /^Hydraulic\d\d.*Valve|PressureControlled\d\dValve|^HydraulicValve\d|OpenCenterValve|LoadSensingValve/],
    // machines and actuators
    ['cylinder', /^HydraulicPumpPiston$/],
    ['pump', /Pump/],
    ['motor', /^(Hydraulic|Pneumatic).*(Motor|Machine)/],
    ['accumulator', /Ackumulator|Accumulator/],
    ['cylinder', /Cylinder[CQ]?$|Piston/],
    // lines, restrictions and boundaries
    ['tank', /Tank/],
    ['plug', /Plug/],
    ['orifice', /Orifice/],
    ['volume', /Volume|Hose/],
    ['line', /TLMlossless|LosslessT?Connector/],
    ['sensor', /[Ss]ensor$/],
    ['boundary-source', /^(Hydraulic|Electric|MechanicTranslational)[CQ]Source$/],
    ['fluid-source', /^(Hydraulic|Pneumatic).*(Source|src)/],
    // electrics (before mechanics: ElectricMotorGear is a motor, ElectricGround no wall)
    ['electric-motor', /^ElectricMotor|^MechanicMotor$/],
    ['resistor', /Resistor/],
    ['capacitor', /Capacit/],
    ['inductor', /Inductance|Inductor/],
    ['electric-ground', /^Electric.*Ground$/],
    ['battery', /Battery/],
    ['voltage-source', /^Electric(Usource|VoltageSource)/],
    ['current-source', /^ElectricIsource/],
    ['switch', /^ElectricSwitch/],
    // mechanics
    ['mass', /Mass|load1D$/],
    ['spring', /^Mechanic(Translational)?Spring/],
    ['torsion-spring', /TorsionalSpring|RotShaft/],
    ['damper', /Damper/],
    ['fixed', /^Mechanic(FixedPosition|FreeLengthWall)/],
    ['inertia', /RotationalInertia/],
    ['gear', /Gear|WormDrive|BallScrew|RackAndPinion/],
    ['pulley', /Pulley/],
    ['lever', /JLink|Lever/],
    ['mechanic-source', /^Mechanic.*(Transformer|Source)$/],
    // signals
    ['gain', /^SignalGain$/],
    ['sum', /^Signal(Add|Sub|Subtract|Sum)$/],
    ['product', /^Signal(Multiply|Divide)$/],
    ['integrator', /Integrator/],
    ['delay', /^Signal(Unit|Variable|)TimeDelay$|^SignalUnitDelay$/],
    ['transfer-function', /TransferFunction|OrderFilter/],
    ['filter', /^Signal[LH]P\dFilter$/],
    ['step', /^Signal(Soft)?Step$|^SignalStepExponentialDelay$/],
    ['sine', /^SignalSineWave$/],
    ['ramp', /^SignalRamp$/],
    ['constant', /^SignalConstant$/],
    ['pulse', /^SignalPulse$/],
    ['square', /^Signal(Square|Pulse)Wave$/],
    ['noise', /Noise/],
    ['staircase', /^SignalStaircase$/],
    ['clock', /^SignalTime(step)?$/],
    ['sink', /^Signal(Sink|Logger)$/],
    ['and', /^SignalAnd$/],
    ['or', /^SignalOr$/],
    ['not', /^SignalNot$/],
    ['xor', /^SignalXor$/],
    ['comparator', /^Signal(GreaterThan|SmallerThan)$/],
    ['latch', /latch$/],
    ['saturation', /^SignalSaturation$/],
    ['characteristic', /^Signal(DeadZone|Hysteresis|RateLimiter|Sign|AbsoluteValue)$/],
    ['lookup-table', /Look[Uu]pTable/],
    ['math-function', /^Signal(Sin|Cos|Tan|Asin|Acos|Atan2?|Sinh|Cosh|Tanh|Exp|Log|Log10|Sqrt|Power|Square|Floor|Ceil|Round|Min|Max|SampleAndHold)$/],
];

/** The symbol family of a type, or null for types drawn as a labelled box (unknown types). */
export function iconFamily(type: string): Family | null {
    for (const [family, pattern] of rules) if (pattern.test(type)) return family;
    return null;
}
