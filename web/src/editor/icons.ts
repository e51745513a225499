// Component icons of our own: a frame coloured by domain with a small glyph per family,
// drawn in the component's frame (centre 0,0; box ±w,±h).
import { s } from '../ui/dom';
import { valveGlyph } from './valveGlyphs';

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

const stroke = { fill: 'none', stroke: 'currentColor', 'stroke-width': 1.5, 'stroke-linejoin': 'round', 'stroke-linecap': 'round' };

function line(points: [number, number][]): SVGPolylineElement {
    return s('polyline', { ...stroke, points: points.map((p) => p.join(',')).join(' ') });
}

function text(label: string, size: number, y = 0): SVGTextElement {
    return s('text', { x: 0, y, 'font-size': size, 'text-anchor': 'middle', 'dominant-baseline': 'central', class: 'icon-text' }, label);
}

function zigzag(x0: number, x1: number, amp: number, n = 6): [number, number][] {
    const pts: [number, number][] = [[x0, 0]];
    const step = (x1 - x0) / (n + 1);
    for (let i = 1; i <= n; ++i) pts.push([x0 + i * step, i % 2 ? -amp : amp]);
    pts.push([x1, 0]);
    return pts;
}

const OPEN_FAMILIES = /Cylinder/;

// Glyphs by family, each scaled to the box (r = the smaller half side).
function glyph(type: string, w: number, h: number, fill: string): SVGElement[] {
    const r = Math.min(w, h) * 0.7;
    const t = type;
    if (/Tank/.test(t)) return [line([[-r, -r * 0.6], [-r, r * 0.6], [r, r * 0.6], [r, -r * 0.6]]), line([[-r * 0.8, 0], [r * 0.8, 0]])];
    if (/Cylinder/.test(t)) {
        // only the barrel is solid: in Hopsan's layout the load sits on the rod, inside the box
        return [s('rect', { ...stroke, class: 'icon-solid', fill, x: -w * 0.8, y: -h * 0.5, width: w * 1.2, height: h }),
            line([[-w * 0.1, -h * 0.5], [-w * 0.1, h * 0.5]]), line([[-w * 0.1, 0], [w * 0.9, 0]])];
    }
    if (/Pump|Motor/.test(t)) {
        return [s('circle', { ...stroke, r }), s('polygon', { fill: 'currentColor', points: `0,${-r} ${-r * 0.35},${-r * 0.45} ${r * 0.35},${-r * 0.45}` })];
    }
    const valve = valveGlyph(t, w, h);
    if (valve) return valve;
    if (/Orifice|Restrict|Throttle/.test(t)) {
        return [s('path', { ...stroke, d: `M${-r},${-r * 0.5} Q0,${-r * 0.05} ${r},${-r * 0.5} M${-r},${r * 0.5} Q0,${r * 0.05} ${r},${r * 0.5}` })];
    }
    if (/Volume|Line|Hose|Accumulator/.test(t)) return [s('rect', { ...stroke, x: -w * 0.8, y: -h * 0.4, width: w * 1.6, height: h * 0.8, rx: h * 0.4 })];
    if (/Spring/.test(t)) return [line(zigzag(-w * 0.9, w * 0.9, h * 0.35))];
    if (/Damper/.test(t)) {
        return [line([[-w * 0.9, 0], [-w * 0.2, 0]]), line([[-w * 0.2, -h * 0.4], [-w * 0.2, h * 0.4]]),
            line([[w * 0.3, -h * 0.5], [-w * 0.4, -h * 0.5], [-w * 0.4, h * 0.5], [w * 0.3, h * 0.5]]), line([[w * 0.3, 0], [w * 0.9, 0]])];
    }
    if (/Fixed|Ground|Reference/.test(t)) {
        const hatch: SVGElement[] = [line([[-r, 0], [r, 0]])];
        for (let i = -2; i <= 2; ++i) hatch.push(line([[i * r * 0.4, 0], [i * r * 0.4 - r * 0.3, r * 0.4]]));
        return hatch;
    }
    if (/Sensor|Transducer|Meter/.test(t)) {
        return [s('circle', { ...stroke, r }), line([[0, 0], [r * 0.6, -r * 0.6]]), s('circle', { fill: 'currentColor', r: 2 })];
    }
    if (/Mass|Inertia|Load/.test(t)) return [text(/Inertia/.test(t) ? 'J' : 'm', r * 1.2)];
    if (/Resistor/.test(t)) return [line(zigzag(-w * 0.8, w * 0.8, h * 0.3))];
    if (/Capacit/.test(t)) return [line([[-w * 0.8, 0], [-r * 0.2, 0]]), line([[-r * 0.2, -r], [-r * 0.2, r]]), line([[r * 0.2, -r], [r * 0.2, r]]), line([[r * 0.2, 0], [w * 0.8, 0]])];
    if (/Inductor/.test(t)) return [s('path', { ...stroke, d: `M${-w * 0.8},0 a${r * 0.3},${r * 0.3} 0 0 1 ${r * 0.6},0 a${r * 0.3},${r * 0.3} 0 0 1 ${r * 0.6},0 a${r * 0.3},${r * 0.3} 0 0 1 ${r * 0.6},0` })];
    if (/Gain/.test(t)) return [s('polygon', { ...stroke, points: `${-w * 0.7},${-h * 0.7} ${w * 0.7},0 ${-w * 0.7},${h * 0.7}` }), text('K', r * 0.6, 0)];
    if (/Add|Subtract|Sum/.test(t)) return [s('circle', { ...stroke, r }), text(/Subtract/.test(t) ? '−' : '+', r * 1.3)];
    if (/Multiply|Product/.test(t)) return [s('circle', { ...stroke, r }), text('×', r * 1.2)];
    if (/Divide/.test(t)) return [s('circle', { ...stroke, r }), text('÷', r * 1.2)];
    if (/Integrat/.test(t)) return [text('∫', r * 1.4)];
    if (/Derivat/.test(t)) return [text('d/dt', r * 0.7)];
    if (/Step/.test(t)) return [line([[-r, r * 0.5], [0, r * 0.5], [0, -r * 0.5], [r, -r * 0.5]])];
    if (/Sink|Scope|Plot/.test(t)) return [s('rect', { ...stroke, x: -r, y: -r * 0.8, width: 2 * r, height: 1.6 * r }), s('path', { ...stroke, d: `M${-r * 0.8},${r * 0.4} C${-r * 0.2},${-r * 1.1} ${r * 0.2},${r * 0.9} ${r * 0.8},${-r * 0.4}` })];
    if (/Sine|Sinus|Wave|Oscill/.test(t)) return [s('path', { ...stroke, d: `M${-r},0 C${-r * 0.5},${-r * 1.2} ${-r * 0.5},${-r * 1.2} 0,0 S${r * 0.5},${r * 1.2} ${r},0` })];
    if (/Ramp/.test(t)) return [line([[-r, r * 0.5], [-r * 0.3, r * 0.5], [r * 0.5, -r * 0.5], [r, -r * 0.5]])];
    if (/Constant|Source/.test(t) && t.startsWith('Signal')) return [text('C', r)];
    if (/Voltage|Current|Pressure|Flow|Force|Velocity|Torque|Source/.test(t)) {
        return [s('circle', { ...stroke, r }), line([[0, r * 0.6], [0, -r * 0.6]]), line([[-r * 0.25, -r * 0.3], [0, -r * 0.6], [r * 0.25, -r * 0.3]])];
    }
    return [text(abbreviation(type), Math.max(8, Math.min(14, r * 0.8)))];
}

/** The icon of a component type sized to its box (half width and height). */
export function componentIcon(type: string, halfWidth: number, halfHeight: number): SVGGElement {
    const domain = domainOf(type);
    const isSub = domain === 'Subsystem';
    const fill = domainColours[domain] ?? '#fff';
    // open symbols leave their box see-through (still clickable) so neighbours placed inside it show
    const open = OPEN_FAMILIES.test(type);
    return s('g', { class: `icon icon-${domain.toLowerCase()}${open ? ' icon-open' : ''}` },
        s('rect', {
            class: open ? 'icon-frame' : 'icon-frame icon-solid', x: -halfWidth, y: -halfHeight, width: 2 * halfWidth, height: 2 * halfHeight,
            rx: isSub ? 6 : 3, fill: open ? 'transparent' : fill,
        }),
        isSub ? s('rect', { class: 'icon-inner', x: -halfWidth + 4, y: -halfHeight + 4, width: 2 * halfWidth - 8, height: 2 * halfHeight - 8, rx: 4, fill: 'none' }) : null,
        ...(isSub ? [text('SUB', Math.min(halfWidth, halfHeight) * 0.5)] : glyph(type, halfWidth, halfHeight, fill)));
}
