// Where a component's parameter ports sit when shown. Hopsan's layout facts (appearance.json)
// give them no place, and the edges are taken by the power and signal ports, so they get a row
// of their own just outside the icon box, above its top edge: they never sit on another port.
import { appearanceOf } from './appearance';
import { isInputVariablePort, type ComponentLayout, type Point } from './geometry';
import type { Component, Port } from '../protocol/types';

/** Widest port marker (a multiport's circle) plus a little air: closer ports are hard to tell apart. */
export const PORT_MARKER_SIZE = 12;
/** From the top edge to the row, and between neighbours in it. */
const ROW_GAP = 14;

/**
 * A read port backed by a "<port>#Value" parameter that Hopsan's icon gives no place (a gain's
 * `k`, not its `in`): Hopsan hides it until the user shows it.
 */
export function isParameterPort(component: Component, port: Port): boolean {
    if (port.kind !== 'read' || !isInputVariablePort(component, port.name)) return false;
    return appearanceOf(component.type)?.ports[port.name] === undefined;
}

/** A parameter port not connected: drawn and hit only while shown (a connected one always is). */
export function hiddenUnlessShown(component: Component, port: Port): boolean {
    return !port.connected && isParameterPort(component, port);
}

/**
 * `layout` with the parameter ports moved to a row centred above the box; one whose saved line
 * ends elsewhere (`known`) stays there, where the author saw it.
 */
export function placeParameterPorts(component: Component, layout: ComponentLayout, known?: Map<string, Point>): ComponentLayout {
    const names = component.ports.filter((p) => isParameterPort(component, p) && !known?.has(p.name)).map((p) => p.name);
    if (names.length === 0) return layout;
    const ports = new Map<string, Point>(layout.ports);
    const y = -layout.halfHeight - ROW_GAP;
    names.forEach((name, i) => ports.set(name, { x: (i - (names.length - 1) / 2) * ROW_GAP, y }));
    return { ...layout, ports };
}
