import { describe, expect, it } from 'vitest';
import { watchStatusText, watchedPlotVariables } from './watchText';
import type { LiveStatus } from './LiveSession';

const status = (phase: LiveStatus['phase'], modelTime = 1.25): LiveStatus =>
    ({ phase, speed: 1, achievedSpeed: 1, behind: false, modelTime, message: '', notice: '' });

describe('watchText', () => {
    it('says the watched session\'s state with its model time', () => {
        expect(watchStatusText(status('starting'))).toBe('Joining the live session…');
        expect(watchStatusText(status('running'))).toBe('Live · t = 1.25 s');
        expect(watchStatusText(status('paused', 2))).toBe('Paused by its owner · t = 2 s');
        expect(watchStatusText(status('stopped', 3))).toBe('Ended · t = 3 s');
    });

    it('plots the streamed sink variables, else the first streamed one', () => {
        expect(watchedPlotVariables(['Scope#in#Value', 'Other#in#Value'], ['Step#out#Value', 'Scope#in#Value'])).toEqual(['Scope#in#Value']);
        expect(watchedPlotVariables(['Scope#in#Value'], ['Step#out#Value', 'Mass#P1#x'])).toEqual(['Step#out#Value']);
        expect(watchedPlotVariables([], [])).toEqual([]);
    });
});
