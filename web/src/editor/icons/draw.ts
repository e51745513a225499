// Drawing primitives shared by all icon families. Every icon is drawn in its component's frame
// (centre 0,0; box ±w,±h) with one stroke width per icon, so symbols of all families look alike.
// Only polylines, polygons, rects, circles and text are made: their coordinates are plain
// attributes, which lets the tests check that every glyph stays inside its box.
import { s } from '../../ui/dom';
import { appearanceOf } from '../../model/appearance';

export type Pt = [number, number];
export type Glyph = SVGElement[];

const round = (v: number) => Math.round(v * 100) / 100;

/** faint: thin and light, for axes and guides behind the curve that matters. */
interface Opts { cls?: string; dashed?: boolean; filled?: boolean; fill?: string; faint?: boolean }

export class Pen {
    /** Stroke width: thinner in small boxes (palette, 10 px signal blocks), at most 1.6 px. */
    readonly sw: number;

    constructor(readonly w: number, readonly h: number, readonly fill = '#fff', private readonly swap = false) {
        this.sw = Math.max(0.8, Math.min(1.6, Math.min(w, h) * 0.1));
    }

    /** The smaller half side: the scale of square symbols. */
    get u(): number { return Math.min(this.w, this.h); }

    /**
     * A pen drawing with x and y exchanged: one drawing (a check valve, a cylinder, a wall) serves
     * both lying and upright boxes. Its w and h are those of the exchanged frame.
     */
    transposed(): Pen { return new Pen(this.h, this.w, this.fill, !this.swap); }

    /** True when the box is upright (taller than wide): families drawn lying then use transposed(). */
    get upright(): boolean { return this.h > this.w; }

    private map([x, y]: Pt): Pt { return this.swap ? [y, x] : [x, y]; }
    private pts(points: Pt[]): string { return points.map((p) => this.map(p).map(round).join(',')).join(' '); }

    private style(o: Opts): Record<string, unknown> {
        return {
            class: o.cls, fill: o.filled ? 'currentColor' : (o.fill ?? 'none'), stroke: 'currentColor', 'stroke-width': o.faint ? round(this.sw * 0.7) : this.sw,
            'stroke-opacity': o.faint ? 0.45 : undefined,
            'stroke-linejoin': 'round', 'stroke-linecap': 'round', 'stroke-dasharray': o.dashed ? `${round(this.sw * 2.5)} ${round(this.sw * 2)}` : undefined,
        };
    }

    line(points: Pt[], o: Opts = {}): SVGElement { return s('polyline', { ...this.style(o), points: this.pts(points) }); }

    poly(points: Pt[], o: Opts = {}): SVGElement { return s('polygon', { ...this.style(o), points: this.pts(points) }); }

    circle(c: Pt, r: number, o: Opts = {}): SVGElement {
        const [cx, cy] = this.map(c);
        return s('circle', { ...this.style(o), cx: round(cx), cy: round(cy), r: round(r) });
    }

    rect(x0: number, y0: number, x1: number, y1: number, o: Opts = {}): SVGElement {
        const [a, b] = [this.map([x0, y0]), this.map([x1, y1])];
        return s('rect', { ...this.style(o), x: round(Math.min(a[0], b[0])), y: round(Math.min(a[1], b[1])), width: round(Math.abs(b[0] - a[0])), height: round(Math.abs(b[1] - a[1])) });
    }

    text(label: string, size: number, at: Pt = [0, 0], cls = 'icon-text'): SVGElement {
        const [x, y] = this.map(at);
        return s('text', { x: round(x), y: round(y), 'font-size': round(size), 'text-anchor': 'middle', 'dominant-baseline': 'central', class: cls }, label);
    }

    /** Text at the largest size up to `max` whose estimated extent fits half sizes hw × hh around `at`. */
    fitText(label: string, max: number, hw: number, hh: number, at: Pt = [0, 0]): SVGElement {
        return this.text(label, Math.max(3, Math.min(max, hh * 2 * 0.85, (hw * 2) / (0.62 * label.length))), at);
    }

    /** A line from a to b with a filled head at b (flow, force and signal arrows). */
    arrow(a: Pt, b: Pt, cls?: string, head = Math.max(2.5, this.sw * 3.2)): Glyph {
        const len = Math.hypot(b[0] - a[0], b[1] - a[1]) || 1;
        const [ux, uy] = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
        const hl = Math.min(head, len * 0.45);
        const base: Pt = [b[0] - ux * hl, b[1] - uy * hl];
        const wing = hl * 0.5;
        return [this.line([a, base], { cls }),
            this.poly([b, [base[0] - uy * wing, base[1] + ux * wing], [base[0] + uy * wing, base[1] - ux * wing]], { cls, filled: true })];
    }

    /** A zigzag spring from a to b with n teeth of amplitude amp across the a-b line. */
    zigzag(a: Pt, b: Pt, amp: number, n = 6, cls?: string): SVGElement {
        const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
        const len = Math.hypot(dx, dy) || 1;
        const [nx, ny] = [-dy / len, dx / len];
        const pts: Pt[] = [a];
        for (let i = 1; i <= n; i++) {
            const t = (i - 0.5) / n;
            const side = i % 2 ? -amp : amp;
            pts.push([a[0] + dx * t + nx * side, a[1] + dy * t + ny * side]);
        }
        pts.push(b);
        return this.line(pts, { cls });
    }

    /** Ground hatching: the line a-b with short strokes on its `side` (+1: left of a→b). */
    hatch(a: Pt, b: Pt, depth: number, side: 1 | -1 = 1, n = 5): Glyph {
        const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
        const len = Math.hypot(dx, dy) || 1;
        const [ux, uy, nx, ny] = [dx / len, dy / len, (-dy / len) * side, (dx / len) * side];
        const out: Glyph = [this.line([a, b], { cls: 'glyph-ground' })];
        const lean = Math.min(depth * 0.7, len / n);
        for (let i = 0; i < n; i++) {
            const t = (i + 1) / n;
            const p: Pt = [a[0] + dx * t, a[1] + dy * t];
            // strokes lean back along the line so they stay between a and b
            out.push(this.line([p, [p[0] + nx * depth - ux * lean, p[1] + ny * depth - uy * lean]], { cls: 'glyph-ground' }));
        }
        return out;
    }

    /** A curve sampled as a polyline (sine, arcs, gate outlines). */
    curve(f: (t: number) => Pt, n = 16, o: Opts = {}): SVGElement {
        const pts: Pt[] = [];
        for (let i = 0; i <= n; i++) pts.push(f(i / n));
        return this.line(pts, o);
    }

    /** An ellipse around c with half axes rx, ry, as a closed polyline (tests can measure it). */
    ellipse(c: Pt, rx: number, ry: number, o: Opts = {}): SVGElement {
        const pts: Pt[] = [];
        for (let i = 0; i < 32; i++) pts.push([c[0] + rx * Math.cos((i * Math.PI) / 16), c[1] + ry * Math.sin((i * Math.PI) / 16)]);
        return this.poly(pts, o);
    }

    /** A rectangle with rounded corners of radius r, as a polygon. */
    roundedRect(x0: number, y0: number, x1: number, y1: number, r: number, o: Opts = {}): SVGElement {
        const k = Math.max(0, Math.min(r, (x1 - x0) / 2, (y1 - y0) / 2));
        const q = Math.PI / 2;
        return this.poly([...Pen.arc([x1 - k, y0 + k], k, -q, 0, 4), ...Pen.arc([x1 - k, y1 - k], k, 0, q, 4),
            ...Pen.arc([x0 + k, y1 - k], k, q, 2 * q, 4), ...Pen.arc([x0 + k, y0 + k], k, 2 * q, 3 * q, 4)], o);
    }

    /** Points of an arc around c from angle a0 to a1 (radians, y down). */
    static arc(c: Pt, r: number, a0: number, a1: number, n = 12): Pt[] {
        const pts: Pt[] = [];
        for (let i = 0; i <= n; i++) {
            const a = a0 + ((a1 - a0) * i) / n;
            pts.push([c[0] + r * Math.cos(a), c[1] + r * Math.sin(a)]);
        }
        return pts;
    }
}

/** Where a type's ports sit in its frame (from Hopsan's appearance facts), by port name. */
export function portsOf(type: string, w: number, h: number): { name: string; at: Pt }[] {
    const ports = appearanceOf(type)?.ports ?? {};
    return Object.entries(ports).map(([name, [fx, fy]]) => ({ name, at: [(fx * 2 - 1) * w, (fy * 2 - 1) * h] as Pt }));
}

/** Power ports (Hopsan names them P…) on the top or bottom edge: where fluid lines enter. */
export function edgePorts(type: string, w: number, h: number): Pt[] {
    return portsOf(type, w, h).filter((p) => /^P/.test(p.name) && Math.abs(Math.abs(p.at[1]) - h) < 1e-6).map((p) => p.at);
}

/**
 * Short lines from the ports on the top and bottom edges to a circle (pumps, sensors,
 * sources): the symbol then visibly joins its lines, as in a circuit diagram.
 */
export function stubsToCircle(p: Pen, ports: Pt[], c: Pt, r: number): Glyph {
    const out: Glyph = [];
    for (const [x, y] of ports) {
        const dx = x - c[0];
        if (Math.abs(dx) >= r * 0.95) continue;
        const dy = Math.sqrt(r * r - dx * dx);
        const end = y < c[1] ? c[1] - dy : c[1] + dy;
        if (Math.abs(end - y) > 0.5) out.push(p.line([[x, y], [x, end]], { cls: 'glyph-port-line' }));
    }
    return out;
}
