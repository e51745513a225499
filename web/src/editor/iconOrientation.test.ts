// @vitest-environment jsdom
import { describe, expect, it, vi } from 'vitest';
import { s } from '../ui/dom';
import { poseTransform, toScene } from '../model/geometry';
import { appearanceOf } from '../model/appearance';
import { localPortPoint } from '../model/appearanceLayout';
import type { Pose } from '../protocol/types';
import { componentIcon } from './icons';
import { orientIcon } from './iconOrientation';
import { CanvasView } from './CanvasView';
import { EditorStore } from './EditorStore';
import { AddComponent, MoveComponents } from './commands';
import { FakeServer } from '../testing/FakeServer';

type Matrix = [number, number, number, number, number, number]; // a b c d e f, as SVG's matrix()

/** Rounded, without −0: matrices of quarter turns compare equal. */
const tidy = (m: number[]) => m.map((x) => Math.round(x * 1e9) / 1e9 + 0) as Matrix;

const times = ([a, b, c, d, e, f]: Matrix, [A, B, C, D, E, F]: Matrix): Matrix =>
    tidy([a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D, a * E + c * F + e, b * E + d * F + f]);

/** The matrix of an SVG transform list of translate, rotate and scale (what poses and icons use). */
function matrixOf(transform: string | null): Matrix {
    let m: Matrix = [1, 0, 0, 1, 0, 0];
    for (const [, op, args] of (transform ?? '').matchAll(/(\w+)\(([^)]*)\)/g)) {
        const v = args.split(/[\s,]+/).map(Number);
        const r = ((v[0] ?? 0) * Math.PI) / 180;
        const step: Matrix = op === 'translate' ? [1, 0, 0, 1, v[0], v[1] ?? 0]
            : op === 'rotate' ? [Math.cos(r), Math.sin(r), -Math.sin(r), Math.cos(r), 0, 0]
                : op === 'scale' ? [v[0], 0, 0, v[1] ?? v[0], 0, 0] : (() => { throw new Error(op); })();
        m = times(m, step);
    }
    return m;
}

/** A component body as the canvas draws it: posed, with the type's icon, then oriented. */
function posedBody(type: string, pose: Pose) {
    const { width, height, ports } = appearanceOf(type)!;
    const layout = {
        halfWidth: width / 2, halfHeight: height / 2,
        ports: new Map(Object.entries(ports).map(([name, [x, y]]) => [name, localPortPoint(width, height, { x, y })])),
    };
    const body = s('g', { class: 'component-body', transform: poseTransform(pose) }, componentIcon(type, layout.halfWidth, layout.halfHeight));
    orientIcon(body, type, pose, layout);
    const icon = () => body.querySelector(':scope > .icon')!;
    /** The icon's matrix on screen: the body's pose, then the icon's own transform. */
    const screen = () => times(matrixOf(body.getAttribute('transform')), matrixOf(icon().getAttribute('transform')));
    return { body, layout, icon, screen };
}

const rotatedAndFlipped: Pose = { x: 100, y: 50, angle: 90, flipped: true };

describe('icons Hopsan keeps upright', () => {
    it('draw the Step source unturned after a rotate and a flip, while its port moves', () => {
        const { layout, screen } = posedBody('SignalStep', rotatedAndFlipped);
        // only the translation to the component's centre is left: no rotation, no mirror
        expect(screen()).toEqual([1, 0, 0, 1, 100, 50]);
        const out = layout.ports.get('out')!;
        expect(toScene({ x: 100, y: 50, angle: 0, flipped: false }, out)).toEqual({ x: 112.5, y: 50 });
        const moved = toScene(rotatedAndFlipped, out);
        expect([Math.round(moved.x * 1e6) / 1e6, Math.round(moved.y * 1e6) / 1e6]).toEqual([100, 62.5]);
    });

    it('stay upright at every quarter turn, flipped or not', () => {
        for (const angle of [0, 90, 180, 270]) {
            for (const flipped of [false, true]) {
                const { screen } = posedBody('SignalSineWave', { x: 7, y: 9, angle, flipped });
                expect(screen(), `${angle} ${flipped}`).toEqual([1, 0, 0, 1, 7, 9]);
            }
        }
    });

    it('fill the turned box of a non-square type, where its ports now are', () => {
        const { icon } = posedBody('SignalSink', { x: 0, y: 0, angle: 90, flipped: false });
        const frame = icon().querySelector('.icon-frame')!;
        // Hopsan's Sink is 40 x 30: a quarter turn makes the box 30 wide and 40 high on screen
        expect([frame.getAttribute('width'), frame.getAttribute('height')]).toEqual(['30', '40']);
    });

    it('keep the icon drawn for an orientation when the component only moves', () => {
        const { body, icon, layout } = posedBody('SignalStep', rotatedAndFlipped);
        const before = icon();
        orientIcon(body, 'SignalStep', { ...rotatedAndFlipped, x: 300 }, layout);
        expect(icon()).toBe(before);
    });

    it('turn and mirror the icons of other types with their component', () => {
        const { screen, icon } = posedBody('SignalGain', rotatedAndFlipped);
        expect(icon().getAttribute('transform')).toBeNull();
        expect(screen()).toEqual(matrixOf(poseTransform(rotatedAndFlipped)));
        expect(screen()).not.toEqual([1, 0, 0, 1, 100, 50]);
    });
});

describe('the canvas', () => {
    it('keeps the Step source upright when it is rotated and flipped, and moves its port', async () => {
        vi.stubGlobal('ResizeObserver', class { observe(): void { /* no layout in jsdom */ } disconnect(): void { /* nothing observed */ } });
        const server = new FakeServer();
        const store = new EditorStore(structuredClone(server.model), server.handle);
        const canvas = new CanvasView(store, { onPortClick: () => undefined, onComponentDoubleClick: () => undefined });
        const upright: Pose = { x: 100, y: 50, angle: 0, flipped: false };
        await store.execute(new AddComponent([], 'SignalStep', 'Step', upright));
        const body = () => canvas.element.querySelector('.component[data-name="Step"] .component-body')!;
        const onScreen = () => times(matrixOf(body().getAttribute('transform')), matrixOf(body().querySelector(':scope > .icon')!.getAttribute('transform')));
        const outPort = () => {
            const marker = body().querySelector('[data-port="out"]')!;
            const local = { x: Number(marker.getAttribute('x')) + Number(marker.getAttribute('width')) / 2, y: Number(marker.getAttribute('y')) + Number(marker.getAttribute('height')) / 2 };
            const at = toScene(store.system.components[0].pose, local);
            return [Math.round(at.x * 1e6) / 1e6 + 0, Math.round(at.y * 1e6) / 1e6 + 0];
        };
        expect(outPort()).toEqual([112.5, 50]);

        await store.execute(new MoveComponents([], [{ name: 'Step', from: upright, to: rotatedAndFlipped }], 'Rotate and flip'));
        expect(body().getAttribute('transform')).toMatch(/scale\(-1,1\) rotate\(90\)/);
        expect(onScreen()).toEqual([1, 0, 0, 1, 100, 50]);
        expect(outPort()).toEqual([100, 62.5]);
        canvas.dispose();
        vi.unstubAllGlobals();
    });
});
