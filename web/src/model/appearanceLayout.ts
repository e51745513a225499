// A component's box and ports from Hopsan's layout facts (appearance.json): the icon's own size
// and each port at its fraction of the box, so that bodies and line ends sit where the author
// saw them in Hopsan. Types without facts (subsystems, unknown types) get no layout here.
import { appearanceOf } from './appearance';
import type { ComponentLayout, Point } from './geometry';
import type { Component } from '../protocol/types';

/** Port fractions -> the component's own frame (centre 0,0), the frame toScene places. */
export function localPortPoint(width: number, height: number, fraction: Point): Point {
    return { x: (fraction.x - 0.5) * width, y: (fraction.y - 0.5) * height };
}

/**
 * The layout from appearance.json, or null when the type has none. A port the facts lack (a
 * model's own extra port) keeps where the author's line ended (`known`).
 */
export function appearanceLayout(component: Component, known: Map<string, Point> | undefined): ComponentLayout | null {
    if (component.system) return null;
    const facts = appearanceOf(component.type);
    if (!facts) return null;
    const [w, h] = [facts.width, facts.height];
    const ports = new Map<string, Point>();
    const unplaced: string[] = [];
    for (const port of component.ports) {
        const f = facts.ports[port.name];
        const at = f ? localPortPoint(w, h, { x: f[0], y: f[1] }) : known?.get(port.name);
        if (at) ports.set(port.name, at); else unplaced.push(port.name);
    }
    // the rest along the bottom edge, so that no port floats inside or off the body
    unplaced.forEach((name, i) => ports.set(name, { x: -w / 2 + (w * (i + 1)) / (unplaced.length + 1), y: h / 2 }));
    return { halfWidth: w / 2, halfHeight: h / 2, ports };
}
