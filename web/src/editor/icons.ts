// Component icons of our own: a frame of the component's size coloured by domain, with the
// symbol of the type's family drawn inside it (ISO 1219 fluid power, mechanics, electrics,
// block diagrams, aircraft, controllers, widgets; see icons/). Types of no family (unknown to
// Hopsan's library) keep a labelled box. The drawing is in the component's frame: centre 0,0,
// box ±w,±h.
import { s } from '../ui/dom';
import { appearanceOf } from '../model/appearance';
import { Pen, type Glyph } from './icons/draw';
import { iconFamily, type Family } from './icons/families';
import { checkValve, directionalValve, pressureValve, shuttleValve } from './icons/valves';
import { accumulator, cylinder, fluidSource, line, orifice, plug, pumpOrMotor, tank, volume } from './icons/fluidPower';
import { sensor } from './icons/sensors';
import { damper, fixed, gear, inertia, lever, mass, mechanicSource, pulley, spring, torsionSpring } from './icons/mechanic';
import { battery, boundarySource, capacitor, electricSwitch, ground, inductor, motor, resistor, source } from './icons/electric';
import { characteristic, comparator, delay, filter, gain, integrator, latch, lookupTable, mathFunction, operatorCircle, saturation, transferFunction } from './icons/signal';
import { clock, constant, sink, waveform } from './icons/sources';
import { gate } from './icons/logic';
import { currentController, attitudeControl, pid, pwm } from './icons/control';
import { counter, functionalFlowBlock, router, steadyState, stopSimulation } from './icons/flowLogic';
import { globe, stateMonitor, timeAccelerator, waypoint } from './icons/navigation';
import { dialGauge, display, lamp, numericInput, slider, toggle } from './icons/widgets';
import { activityNode } from './icons/activityDiagram';
import { aircraft, atmosphere, combustionChamber, flightRecorder, fuelTank, jetEngine, propeller, rocket, wind } from './icons/aero';
import { combustionEngine, forkLift, swashPlate, valvePlate, vehicle } from './icons/machines';
import { fmu, interfacePort } from './icons/connectivity';
import { circularSegment, contours, passThrough, script, signalBus, systemPort } from './icons/special';

export { iconFamily, type Family } from './icons/families';

export const domainColours: Record<string, string> = {
    Hydraulic: '#e3eefc',
    Mechanic: '#e4f4e6',
    Signal: '#f1f1f1',
    Electric: '#fdf0dc',
    Pneumatic: '#dff5f5',
    Aero: '#ece6f7',
    Other: '#f6f0e8',
    Subsystem: '#fff8d6',
};

export function domainOf(type: string): string {
    for (const d of ['Hydraulic', 'Mechanic', 'Signal', 'Electric', 'Pneumatic', 'Aero']) if (type.startsWith(d)) return d;
    if (type === 'Subsystem' || type === 'ConditionalSubsystem') return 'Subsystem';
    return 'Other';
}

/** Short text for the generic icon: capitals of the type without its domain. */
export function abbreviation(type: string): string {
    const rest = type.replace(/^(Hydraulic|Mechanic|Signal|Electric|Pneumatic|Aero)/, '') || type;
    const caps = rest.match(/[A-Z0-9]/g)?.join('') ?? rest;
    return (caps.length >= 2 ? caps : rest).slice(0, 4);
}

type Draw = (p: Pen, type: string) => Glyph;

/** The drawing of each family. */
const drawings: Record<Family, Draw> = {
    'directional-valve': directionalValve, 'pressure-valve': pressureValve, 'check-valve': checkValve, 'shuttle-valve': shuttleValve,
    pump: (p, t) => pumpOrMotor(p, t, false), motor: (p, t) => pumpOrMotor(p, t, true),
    cylinder, accumulator, volume, line, orifice, tank, plug, 'fluid-source': fluidSource,
    sensor,
    mass, spring, damper, fixed, inertia, 'torsion-spring': torsionSpring, gear, pulley, lever, 'mechanic-source': mechanicSource,
    resistor, capacitor, inductor, 'voltage-source': (p) => source(p, 'voltage'), 'current-source': (p) => source(p, 'current'),
    battery, 'electric-ground': ground, 'electric-motor': motor, switch: electricSwitch, 'boundary-source': boundarySource,
    gain, sum: operatorCircle, product: operatorCircle, integrator, delay, 'transfer-function': transferFunction, filter,
    step: (p, t) => waveform(p, 'step', t), sine: (p) => waveform(p, 'sine'), ramp: (p) => waveform(p, 'ramp'), constant,
    pulse: (p) => waveform(p, 'pulse'), square: (p) => waveform(p, 'square'), noise: (p) => waveform(p, 'noise'),
    staircase: (p) => waveform(p, 'staircase'), clock, sink,
    and: (p) => gate(p, 'and'), or: (p) => gate(p, 'or'), not: (p) => gate(p, 'not'), xor: (p) => gate(p, 'xor'),
    comparator, latch, saturation, characteristic, 'lookup-table': lookupTable, 'math-function': mathFunction,
    pid, 'attitude-control': attitudeControl, 'current-controller': currentController, pwm, 'functional-flow': functionalFlowBlock, router,
    counter, 'steady-state': steadyState, stop: stopSimulation, globe, waypoint, 'state-monitor': stateMonitor, 'time-accelerator': timeAccelerator,
    'dial-gauge': dialGauge, lamp, slider, toggle, display, 'numeric-input': numericInput, 'signal-bus': signalBus, 'circular-segment': circularSegment,
    activity: activityNode,
    aircraft, rocket, 'jet-engine': jetEngine, propeller, 'aero-fuel-tank': fuelTank, 'combustion-chamber': combustionChamber, atmosphere, wind,
    'flight-recorder': flightRecorder, vehicle, engine: combustionEngine, 'fork-lift': forkLift, 'valve-plate': valvePlate, 'swash-plate': swashPlate,
    interface: interfacePort, fmu, script, 'pass-through': passThrough, contours, 'system-port': systemPort,
};

/** The labelled box of types without a family. */
function fallback(type: string, w: number, h: number): Glyph {
    const label = abbreviation(type);
    // as large as fits, up to 14 px: the frame's size is Hopsan's, the label must stay inside it
    const size = Math.max(2, Math.min(14, Math.min(w, h) * 0.56, (2 * h) / 0.95, (2 * w) / (0.62 * label.length)));
    return [s('text', { x: 0, y: 0, 'font-size': Math.round(size * 100) / 100, 'text-anchor': 'middle', 'dominant-baseline': 'central', class: 'icon-text icon-fallback' }, label)];
}

/**
 * Half sizes with the type's own aspect (Hopsan's icon size) that fit maxW × maxH, no side under
 * `min`: small icons (the palette's) then look like the component on the canvas.
 */
export function fittedHalfSize(type: string, maxW: number, maxH: number, min = maxH / 2): [number, number] {
    const a = appearanceOf(type);
    if (!a || !(a.width > 0 && a.height > 0)) return [maxW, maxH];
    const k = Math.min(maxW / a.width, maxH / a.height) * 2;
    return [Math.max(min, (a.width * k) / 2), Math.max(min, (a.height * k) / 2)];
}

/** The icon of a component type sized to its box (half width and height). */
export function componentIcon(type: string, halfWidth: number, halfHeight: number): SVGGElement {
    const domain = domainOf(type);
    const isSub = domain === 'Subsystem';
    const fill = domainColours[domain] ?? '#fff';
    const family = isSub ? null : iconFamily(type);
    // open symbols leave their box see-through (still clickable) so neighbours placed inside it
    // show: in Hopsan's layouts the load sits on a cylinder's rod, inside the cylinder's box
    const open = family === 'cylinder' && /Cylinder/.test(type);
    const glyph = isSub
        ? [s('text', { x: 0, y: 0, 'font-size': Math.min(halfWidth, halfHeight) * 0.5, 'text-anchor': 'middle', 'dominant-baseline': 'central', class: 'icon-text' }, 'SUB')]
        : family ? drawings[family](new Pen(halfWidth, halfHeight, fill), type) : fallback(type, halfWidth, halfHeight);
    return s('g', { class: `icon icon-${domain.toLowerCase()}${open ? ' icon-open' : ''}`, 'data-family': family ?? undefined },
        s('rect', {
            class: open ? 'icon-frame' : 'icon-frame icon-solid', x: -halfWidth, y: -halfHeight, width: 2 * halfWidth, height: 2 * halfHeight,
            rx: isSub ? 6 : 3, fill: open ? 'transparent' : fill,
        }),
        isSub ? s('rect', { class: 'icon-inner', x: -halfWidth + 4, y: -halfHeight + 4, width: 2 * halfWidth - 8, height: 2 * halfHeight - 8, rx: 4, fill: 'none' }) : null,
        ...glyph);
}
