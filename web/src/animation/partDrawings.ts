// Our own drawings of the moving parts, made from the component's own icon (src/editor/icons):
// the part that moves (a cylinder's piston and rod, a valve's envelopes, a mass, a gauge's
// pointer) is copied into a group over the icon and the original hidden while animating; a
// machine gets a mark on its rotor. The description (descriptions.ts) says how far and about
// which pivot a part moves; the drawing is ours, never Hopsan's artwork.
import { s } from '../ui/dom';
import { iconFamily } from '../editor/icons';
import type { AnimationDescription } from './descriptions';
import type { MovableState } from './movableState';

/** What a component's drawing needs at one instant. */
export interface PartFrame {
    /** One state per movable of the description. */
    states: MovableState[];
    /** Per movable, per data entry: the value, undefined when unknown. */
    values: (number | undefined)[][];
    /** The pressure scale's colour of a pressure. */
    pressureColour(p: number): string;
}

export interface PartDrawing {
    /** The group over the icon holding the moving copies (inside `.icon`, so it turns as the icon does). */
    readonly element: SVGGElement;
    update(frame: PartFrame): void;
    /**
     * How far a port that moves with a part (a rod's end, a mass's sides) is from its place, in
     * the group's frame, as of the last update; null for a port that stays. Lines follow it.
     */
    portShift(port: string): [number, number] | null;
    /** Shows the originals again and removes the copies. */
    remove(): void;
}

/** Where copies are drawn: shifted by x, y, then turned or stretched by `then` (an SVG transform). */
interface Placement { x: number; y: number; then?: string }

/** The icon's frame: Hopsan's icon size (the description's coordinates) on our half sizes. */
interface Frame { kx: number; ky: number; hw: number; hh: number }

const num = (el: Element | null, name: string) => Number(el?.getAttribute(name) ?? 0);

/** Children of the icon that are the symbol itself (not its box, nor the lines to the ports). */
function symbolParts(icon: SVGGElement): SVGElement[] {
    return [...icon.children].filter((c): c is SVGElement =>
        c instanceof SVGElement && !c.matches('.icon-frame, .glyph-port-line, .icon-inner, title, .animation-parts'));
}

/**
 * A drawing whose copies of `originals` move as `place(frame)` says; `ports` move with them
 * (each by the placement's shift, or by its own function of the frame).
 */
class CopiedParts implements PartDrawing {
    readonly element: SVGGElement;
    private readonly moving: SVGGElement;
    private transform = '';
    private readonly shifts = new Map<string, [number, number]>();

    constructor(icon: SVGGElement, private readonly originals: SVGElement[], private readonly place: (frame: PartFrame) => Placement,
        private readonly ports: Map<string, ((frame: PartFrame) => [number, number]) | null> = new Map(),
        extra: SVGElement[] = [], private readonly paint?: (frame: PartFrame) => void) {
        this.moving = s('g', { class: 'movable-part' }, ...originals.map((o) => o.cloneNode(true) as SVGElement));
        this.element = s('g', { class: 'animation-parts' }, ...extra, this.moving);
        for (const o of originals) o.style.visibility = 'hidden';
        icon.append(this.element);
    }

    /** Adds shapes of ours that move with the copies. */
    add(...shapes: SVGElement[]): void { this.moving.append(...shapes); }

    update(frame: PartFrame): void {
        const at = this.place(frame);
        const transform = `${translate(at.x, at.y)}${at.then ? ` ${at.then}` : ''}`;
        if (transform !== this.transform) {
            this.transform = transform;
            this.moving.setAttribute('transform', transform);
        }
        for (const [port, shift] of this.ports) this.shifts.set(port, shift ? shift(frame) : [at.x, at.y]);
        this.paint?.(frame);
    }

    portShift(port: string): [number, number] | null { return this.shifts.get(port) ?? null; }

    remove(): void {
        for (const o of this.originals) o.style.visibility = '';
        this.element.remove();
    }
}

/** The ports that move with movable `m` (with its shift). */
const movingPorts = (d: AnimationDescription, m: number) =>
    new Map((d.movables[m]?.movingPorts ?? []).map((p) => [p.port, null] as [string, null]));

const round = (v: number) => Math.round(v * 100) / 100;
const translate = (x: number, y: number) => `translate(${round(x)},${round(y)})`;

/** The index of the first movable that moves (by translation, or by rotation), or −1. */
function firstMoving(d: AnimationDescription, rotating: boolean): number {
    return d.movables.findIndex((m) => m.move?.some((e) => (rotating ? e.a !== 0 : e.x !== 0 || e.y !== 0)));
}

/**
 * A cylinder: piston and rod move together by the rod's movement (the part with the rod's
 * port); at data 0 the piston is at the barrel's start (Hopsan's rest: rod in). The chambers
 * either side of the piston take the colour of their pressures.
 */
function cylinder(icon: SVGGElement, d: AnimationDescription, f: Frame): PartDrawing | null {
    const barrel = icon.querySelector('.glyph-barrel');
    const piston = icon.querySelector<SVGElement>('.glyph-piston');
    const rods = [...icon.querySelectorAll<SVGElement>('.glyph-rod')];
    const rodPart = d.movables.findIndex((m) => m.movingPorts?.length && m.move?.length);
    const part = rodPart >= 0 ? rodPart : firstMoving(d, false);
    if (!barrel || !piston || part < 0) return null;
    const [bx, bw, by, bh] = [num(barrel, 'x'), num(barrel, 'width'), num(barrel, 'y'), num(barrel, 'height')];
    const [px, pw] = [num(piston, 'x'), num(piston, 'width')];
    const wall = Math.max(0.8, Number(barrel.getAttribute('stroke-width') ?? 1));
    const rest = bx + wall - px;
    // the first part that reads a pressure is chamber A's (cap side), the next chamber B's
    const pressures = d.movables.map((m, i) => m.data.findIndex(([, v]) => v === 'Pressure') >= 0 ? i : -1).filter((i) => i >= 0);
    const chamberA = s('rect', { class: 'chamber', x: bx, y: by, height: bh, width: 0, fill: 'none', stroke: 'none' });
    const chamberB = s('rect', { class: 'chamber', x: bx, y: by, height: bh, width: 0, fill: 'none', stroke: 'none' });
    const pressureOf = (frame: PartFrame, movable: number | undefined) => {
        if (movable === undefined) return undefined;
        const at = d.movables[movable].data.findIndex(([, v]) => v === 'Pressure');
        return frame.values[movable]?.[at];
    };
    const shift = (frame: PartFrame) => rest + frame.states[part].dx * f.kx;
    return new CopiedParts(icon, [piston, ...rods], (frame) => ({ x: shift(frame), y: frame.states[part].dy * f.ky }),
        movingPorts(d, part), [chamberA, chamberB], (frame) => {
            const x = px + shift(frame);
            chamberA.setAttribute('width', String(round(Math.max(0, x - bx))));
            chamberB.setAttribute('x', String(round(x + pw)));
            chamberB.setAttribute('width', String(round(Math.max(0, bx + bw - x - pw))));
            const [pa, pb] = [pressureOf(frame, pressures[0]), pressureOf(frame, pressures[1])];
            chamberA.setAttribute('fill', pa === undefined ? 'none' : frame.pressureColour(pa));
            chamberB.setAttribute('fill', pb === undefined ? 'none' : frame.pressureColour(pb));
        });
}

/** A part that translates: copies of `originals` shifted by the movable's displacement. */
function sliding(icon: SVGGElement, d: AnimationDescription, f: Frame, originals: SVGElement[]): PartDrawing | null {
    const part = firstMoving(d, false);
    if (part < 0 || originals.length === 0) return null;
    // a value far out of the description's range (a wrong unit) keeps the part near its box
    const clamp = (v: number, half: number) => Math.max(-4 * half, Math.min(4 * half, v));
    return new CopiedParts(icon, originals, (frame) => ({ x: clamp(frame.states[part].dx * f.kx, f.hw), y: clamp(frame.states[part].dy * f.ky, f.hh) }),
        movingPorts(d, part));
}

/** A part that turns about its pivot: `originals` drawn at `drawnAngle` (degrees, clockwise) turn to the movable's angle. */
function turning(icon: SVGGElement, d: AnimationDescription, f: Frame, originals: SVGElement[], pivot: [number, number] | null,
    drawnAngle: number, extra: SVGElement[] = []): PartDrawing | null {
    const part = firstMoving(d, true);
    if (part < 0 || (originals.length === 0 && extra.length === 0)) return null;
    const m = d.movables[part];
    const [cx, cy] = pivot ?? [(m.start[0] + (m.origin?.[0] ?? 0)) * f.kx - f.hw, (m.start[1] + (m.origin?.[1] ?? 0)) * f.ky - f.hh];
    const drawing = new CopiedParts(icon, originals, (frame) => ({ x: 0, y: 0, then: `rotate(${round(frame.states[part].angle - drawnAngle)},${round(cx)},${round(cy)})` }));
    // new shapes of ours (a rotor mark) turn with the copies
    drawing.add(...extra);
    return drawing;
}

/** A machine's rotor: a mark across its circle that turns with the shaft angle. */
function rotor(icon: SVGGElement, d: AnimationDescription, f: Frame): PartDrawing | null {
    const circle = icon.querySelector('.glyph-machine');
    if (!circle) return null;
    const [cx, cy, r] = [num(circle, 'cx'), num(circle, 'cy'), num(circle, 'r')];
    const mark = s('g', { class: 'rotor-mark' },
        s('line', { x1: cx - r * 0.55, y1: cy, x2: cx + r * 0.55, y2: cy, stroke: 'currentColor', 'stroke-width': 1.2, 'stroke-dasharray': '2 1.5' }),
        s('circle', { cx: cx + r * 0.55, cy, r: Math.max(1.2, r * 0.09), fill: 'currentColor' }));
    return turning(icon, d, f, [], [cx, cy], 0, [mark]);
}

/**
 * A spring: its coil stretched between its two ends, each moving with its port (the parts
 * that carry the ports P1 and P2), the box's sides at rest.
 */
function stretched(icon: SVGGElement, d: AnimationDescription, f: Frame): PartDrawing | null {
    const endOf = (port: string) => d.movables.findIndex((m) => m.movingPorts?.some((p) => p.port === port) && m.move?.length);
    const [left, right] = [endOf('P1'), endOf('P2')];
    const originals = symbolParts(icon);
    if (left < 0 || right < 0 || originals.length === 0) return null;
    const ends = (frame: PartFrame) => [frame.states[left].dx * f.kx, frame.states[right].dx * f.kx];
    return new CopiedParts(icon, originals, (frame) => {
        const [dl, dr] = ends(frame);
        // the coil from −hw + dl to hw + dr: scaled about the left side, which moved by dl
        const k = Math.max(0.1, (2 * f.hw + dr - dl) / (2 * f.hw));
        return { x: -f.hw + dl, y: 0, then: `scale(${round(k)},1) translate(${round(f.hw)},0)` };
    }, new Map([['P1', (frame: PartFrame) => [ends(frame)[0], 0]], ['P2', (frame: PartFrame) => [ends(frame)[1], 0]]]));
}

/** A volume: its symbol filled with the colour of its pressure. */
function filled(icon: SVGGElement, d: AnimationDescription): PartDrawing | null {
    const part = d.movables.findIndex((m) => m.colour?.length);
    const shape = icon.querySelector<SVGElement>('.glyph-volume');
    if (part < 0 || !shape) return null;
    const at = d.movables[part].colour![0].data;
    const fill = shape.cloneNode(true) as SVGElement;
    fill.setAttribute('fill-opacity', '0.55');
    const element = s('g', { class: 'animation-parts' }, fill);
    // under the symbol's own lines
    shape.before(element);
    let colour = '';
    return {
        element,
        update: (frame) => {
            const p = frame.values[part]?.[at];
            const next = p === undefined ? 'none' : frame.pressureColour(p);
            if (next !== colour) fill.setAttribute('fill', (colour = next));
        },
        portShift: () => null,
        remove: () => element.remove(),
    };
}

/**
 * An orifice: the two sides of its restriction part as its opening (Kc, or the area A) grows,
 * each by its movable's displacement (the one that starts above the line moves the upper
 * side); at most half the box's half height, so a wrong unit cannot throw them out of it.
 */
function opening(icon: SVGGElement, d: AnimationDescription, f: Frame): PartDrawing | null {
    const sides = [...icon.querySelectorAll<SVGElement>('.glyph-throttle')];
    const upper = d.movables.findIndex((m) => m.start[1] < 0 && m.move?.length);
    const lower = d.movables.findIndex((m) => m.start[1] > 0 && m.move?.length);
    if (sides.length !== 2 || upper < 0 || lower < 0) return null;
    const gap = (frame: PartFrame, part: number) => Math.min(f.hh * 0.5, Math.abs(frame.states[part].dy * f.ky));
    let copies: SVGElement[] = [];
    const drawing: CopiedParts = new CopiedParts(icon, sides, () => ({ x: 0, y: 0 }), new Map(), [], (frame) => {
        if (copies.length === 0) copies = [...drawing.element.querySelectorAll<SVGElement>('.movable-part > .glyph-throttle')];
        copies[0]?.setAttribute('transform', translate(0, -gap(frame, upper)));
        copies[1]?.setAttribute('transform', translate(0, gap(frame, lower)));
    });
    return drawing;
}

/** Families whose parts are left still: their movement is not one a reader follows. */
const still = new Set(['torsion-spring', 'damper']);

/**
 * The drawing of a component's moving parts over its icon (`icon`: the `.icon` group, our
 * half sizes `hw`, `hh`), or null when none of its parts is drawn moving.
 */
export function partDrawing(type: string, d: AnimationDescription, icon: SVGGElement, hw: number, hh: number): PartDrawing | null {
    const f: Frame = { kx: (2 * hw) / d.size[0], ky: (2 * hh) / d.size[1], hw, hh };
    const family = iconFamily(type);
    if (family && still.has(family)) return null;
    switch (family) {
    case 'cylinder': return cylinder(icon, d, f);
    case 'mass': return sliding(icon, d, f, symbolParts(icon).concat([...icon.querySelectorAll<SVGElement>(':scope > .icon-frame')]));
    case 'sensor': {
        const gauge = icon.querySelector('.glyph-gauge');
        // our pointer is drawn at 45° up to the right (icons/sensors.ts)
        return turning(icon, d, f, [...icon.querySelectorAll<SVGElement>('.glyph-pointer')], gauge ? [num(gauge, 'cx'), num(gauge, 'cy')] : null, -45);
    }
    case 'pump': case 'motor': return rotor(icon, d, f);
    case 'spring': return stretched(icon, d, f);
    case 'volume': return filled(icon, d);
    case 'orifice': return opening(icon, d, f);
    case 'shuttle-valve': case 'check-valve': return sliding(icon, d, f, [...icon.querySelectorAll<SVGElement>('.glyph-ball')]);
    default: break;
    }
    if (firstMoving(d, false) >= 0) return sliding(icon, d, f, symbolParts(icon));
    if (firstMoving(d, true) >= 0) {
        const needle = s('line', { class: 'needle', x1: 0, y1: 0, x2: Math.min(hw, hh) * 0.8, y2: 0, stroke: '#c0392b', 'stroke-width': 1.5 });
        return turning(icon, d, f, [], null, 0, [needle]);
    }
    if (d.movables.some((m) => m.colour?.length)) return filled(icon, d);
    return null;
}
