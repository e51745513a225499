// Where a movable part is at one instant, from its description and the values of its port
// variables: displacement, angle, scale and colour. As Hopsan's GUI applies its descriptions,
// each is the rest value *less* the change per unit times the value (divided by the divisor
// parameter): a C-type cylinder's P3 position runs from 0 to −s_l while its rod goes out, and
// its movement is +77.5 px per stroke. Pure, so that the mapping is tested without a drawing.
import type { Movable } from './descriptions';

/** The part's pose relative to rest: `dx`, `dy` in icon pixels, `angle` in degrees (absolute, with the start angle). */
export interface MovableState { dx: number; dy: number; angle: number; sx: number; sy: number; colour: [number, number, number] | null }

/**
 * `value(i)`: the value of the part's `data[i]`, undefined when unknown (the part stays at rest
 * for it); `parameter(name)`: a component parameter's number (a divisor), undefined when none.
 */
export function movableState(m: Movable, value: (i: number) => number | undefined,
    parameter: (name: string) => number | undefined): MovableState {
    const v = (i: number) => value(i) ?? 0;
    // a divisor that is missing, not a number or 0 divides by 1: the part still moves
    const per = (divisor?: string) => {
        const d = divisor ? parameter(divisor) : undefined;
        return d !== undefined && Number.isFinite(d) && d !== 0 ? d : 1;
    };
    const state: MovableState = { dx: 0, dy: 0, angle: m.start[2], sx: m.initScale?.[0] ?? 1, sy: m.initScale?.[1] ?? 1, colour: null };
    for (const e of m.move ?? []) {
        const k = (v(e.data) * (e.multiplier ? parameter(e.multiplier) ?? 1 : 1)) / per(e.divisor);
        state.dx -= e.x * k;
        state.dy -= e.y * k;
        state.angle -= e.a * k;
    }
    for (const e of m.resize ?? []) {
        const k = (v(e.data) - (e.minus !== undefined ? v(e.minus) : 0)) / per(e.divisor);
        state.sx -= e.x * k;
        state.sy -= e.y * k;
    }
    if (m.colour && m.initColour) {
        const rgb = [...m.initColour] as [number, number, number];
        for (const e of m.colour) {
            const k = v(e.data) / per(e.divisor);
            for (let c = 0; c < 3; ++c) rgb[c] -= e.rgb[c] * k;
        }
        state.colour = rgb.map((c) => Math.max(0, Math.min(255, Math.round(c)))) as [number, number, number];
    }
    return state;
}
