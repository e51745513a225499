// The animation descriptions of our own format (scripts/extractAnimation.mjs writes them from
// Hopsan's measured facts): which port variables move which part of a component, and how.
import extract from './animation.generated.json';

/** [port, variable] as the results name it (Comp#Port#Variable). */
export type DataRef = [port: string, variable: string];
export type Point = [x: number, y: number];

/** Displacement per unit of `data[data]`: x, y in icon pixels, a in degrees (clockwise), taken away from the rest position (movableState.ts). */
export interface Movement { x: number; y: number; a: number; data: number; divisor?: string; multiplier?: string }
/** Scale change per unit of `data[data]` (less `data[minus]` when set), taken away from the initial scale. */
export interface Resize { x: number; y: number; data: number; minus?: number; divisor?: string }
/** Colour change (r, g, b per unit) of `data[data]`, taken away from the initial colour. */
export interface ColourChange { rgb: [number, number, number]; data: number; divisor?: string }

export interface Movable {
    data: DataRef[];
    /** Position and angle at rest (data 0), in the icon frame. */
    start: [x: number, y: number, a: number];
    move?: Movement[];
    /** The pivot of rotations, relative to `start`. */
    origin?: Point;
    resize?: Resize[];
    initScale?: Point;
    initColour?: [number, number, number];
    colour?: ColourChange[];
    /** Ports that move with the part, at these icon positions at rest. */
    movingPorts?: { port: string; at: Point }[];
    /** The user may drag the part to set the port's value (min/max per axis, value per pixel). */
    adjustable?: { port: string; dataname: string; x: Point; y: Point; gain: Point };
    /** The user may click the part to toggle the port's value. */
    switchable?: { port: string; dataname: string; on: number; off: number; momentary: boolean };
    indicator?: { port: string; dataname: string };
}

/** A type's animation: its icon size (the frame of all coordinates) and its movable parts. */
export interface AnimationDescription { size: Point; movables: Movable[] }

const types = (extract as unknown as { types: Record<string, AnimationDescription> }).types;

/** The animation of a component type, or undefined when Hopsan animates none of its parts. */
export function animationOf(type: string): AnimationDescription | undefined {
    return types[type];
}

/** Every animated type (for tests and docs). */
export function animatedTypes(): string[] {
    return Object.keys(types);
}
