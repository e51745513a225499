import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { FakeServer } from '../testing/FakeServer';
import { defaultControls } from './defaultControls';
import { INTERACTIVE_TYPES, type Interaction } from './interactiveTypes';
import type { LiveControl } from './liveControls';
import type { Component, System } from '../protocol/types';

type Movable = { adjustable?: Record<string, string>[]; switchable?: Record<string, string>[] };

/** Hopsan's interactive movables as ../shared/reference/animation.json lists them. */
function interactionsInReference(): Record<string, Interaction> {
    const reference = JSON.parse(readFileSync(new URL('../../../../shared/reference/animation.json', import.meta.url), 'utf8')) as
        { types: Record<string, { movables?: Movable[] }> };
    const found: Record<string, Interaction> = {};
    for (const [type, { movables = [] }] of Object.entries(reference.types)) {
        for (const m of movables) {
            const a = m.adjustable?.[0];
            const s = m.switchable?.[0];
            if (a) {
                // the drag is along x unless the x gain is 0 (the slider block: along y)
                const axis = Number(a.xgain) !== 0 ? 'x' : 'y';
                found[type] = { kind: 'adjustable', port: a.port, dataname: a.dataname, min: Number(a[`${axis}min`]), max: Number(a[`${axis}max`]), gain: Number(a[`${axis}gain`]) };
            } else if (s) {
                found[type] = { kind: 'switchable', port: s.port, dataname: s.dataname, off: Number(s.offvalue), on: Number(s.onvalue) };
            }
        }
    }
    return found;
}

const component = (name: string, type: string, x = 0, y = 0): Component =>
    ({ name, type, kind: 'S', pose: { x, y, angle: 0, flipped: false }, ports: [], parameters: [] });
const system = (...components: Component[]): System => ({ ...new FakeServer().model.system, components });

describe('default live controls', () => {
    it('the interactive types are those of animation.json, with its ports, ranges, gains and values', () => {
        expect(INTERACTIVE_TYPES).toEqual(interactionsInReference());
    });

    it('a 4/3 valve gets a slider over its spool range, a switch a switch, under the component', () => {
        const live = new Set(['Valve.in', 'Switch.state', 'Step.y_A']);
        const controls = defaultControls(system(component('Valve', 'Hydraulic43Valve', 100, 40), component('Switch', 'ElectricSwitch', -50, 0), component('Step', 'SignalStep')), [], live, []);
        expect(controls).toEqual([
            { kind: 'slider', name: 'Valve.in', min: -0.01, max: 0.01, x: 100, y: 88, path: [] },
            { kind: 'switch', name: 'Switch.state', min: 0, max: 1, off: 0, on: 1, x: -50, y: 48, path: [] },
        ]);
    });

    it('none where the input is fed by a connection (not a live value) or a saved control binds it; subsystem names have their path', () => {
        const valve = component('Valve', 'Hydraulic42Valve2');
        expect(defaultControls(system(valve), [], new Set(['Step.y_A']), [])).toEqual([]);
        const saved: LiveControl[] = [{ kind: 'knob', name: 'Valve.in', min: 0, max: 1, x: 0, y: 0, path: [] }];
        expect(defaultControls(system(valve), [], new Set(['Valve.in']), saved)).toEqual([]);
        const inside = defaultControls(system(valve), ['Sub'], new Set(['Sub$Valve.in#Value']), []);
        // a negative gain: the range still runs from low to high
        expect(inside).toEqual([{ kind: 'slider', name: 'Sub$Valve.in#Value', min: 0, max: 0.01, x: 0, y: 48, path: ['Sub'] }]);
    });
});
