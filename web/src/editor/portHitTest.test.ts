import { describe, expect, it } from 'vitest';
import { pickPort, type PortTarget } from './portHitTest';

const port = (port: string, x: number, y: number, nodeType: string, power: boolean): PortTarget =>
    ({ ref: { component: 'Valve', port }, at: { x, y }, nodeType, power });

// the 4/3 valve's tank port with a signal input drawn right beside it
const targets = [port('PT', 0, 0, 'NodeHydraulic', true), port('x_pb', 3, 1, 'NodeSignal', false), port('PA', 40, 0, 'NodeHydraulic', true)];

describe('port hit test', () => {
    it('takes the power port under the pointer before a signal port nearer to it', () => {
        expect(pickPort(targets, { x: 3, y: 1 }, 7)).toEqual({ component: 'Valve', port: 'PT' });
    });

    it('takes the nearest port of a kind, and none out of reach', () => {
        expect(pickPort(targets, { x: 36, y: 0 }, 7)?.port).toBe('PA');
        expect(pickPort(targets, { x: 20, y: 20 }, 7)).toBeNull();
    });

    it('drops a dragged connection only on a port of its node type', () => {
        expect(pickPort(targets, { x: 3, y: 1 }, 7, 'NodeSignal')?.port).toBe('x_pb');
        expect(pickPort(targets, { x: 1, y: 0 }, 7, 'NodeMechanic')).toBeNull();
    });
});
