import { describe, expect, it } from 'vitest';
import { differencesFromLatest, differencesText, parameterTexts } from './runDifferences';
import type { JobInfo, Model } from '../protocol/types';

const job = (id: number, differing: Record<string, string>, truncated = false): JobInfo => ({
    id, model_id: 4, state: 'done', progress: 1, error: '', created_at: 0, started_at: 0, finished_at: 1, steps: 100,
    settings: { start: 0, step: 0.001, stop: 1, log_samples: 0 }, name: '', pinned: false, results_dropped: false,
    differing_parameters: differing, ...(truncated ? { differing_parameters_truncated: true } : {}),
});

const param = (name: string, value: string) => ({ name, value, unit: '', description: '', type: 'double' as const });
const pose = { x: 0, y: 0, angle: 0, flipped: false };
const model: Model = {
    name: 'Servo',
    system: {
        name: 'Servo', type: 'Subsystem', timestep: 0.001, inherit_timestep: false, ports: [], connections: [],
        parameters: [param('mass', '10')],
        components: [
            { name: 'GainP', type: 'SignalGain', kind: 'S', pose, ports: [], parameters: [param('k#Value', '0.0264249')] },
            {
                name: 'Sub', type: 'Subsystem', kind: 'system', pose, ports: [], parameters: [param('d', '2')],
                system: {
                    name: 'Sub', type: 'Subsystem', timestep: 0.001, inherit_timestep: true, ports: [], connections: [], parameters: [param('d', '2')],
                    components: [{ name: 'Spring', type: 'MechanicSpring', kind: 'C', pose, ports: [], parameters: [param('k', '1e5')] }],
                },
            },
        ],
    },
};

describe('parameterTexts', () => {
    it('names every parameter by the server\'s path: system parameters, Comp.param, start values, Sub$Comp.param', () => {
        expect([...parameterTexts(model)]).toEqual([
            ['mass', '10'], ['GainP.k#Value', '0.0264249'], ['Sub.d', '2'], ['Sub$Spring.k', '1e5'],
        ]);
    });
});

describe('differencesFromLatest', () => {
    const texts = parameterTexts(model);
    const now = (path: string) => texts.get(path);

    it('a run that used another value than the model says now, against a latest run that used the model\'s', () => {
        expect(differencesFromLatest(job(3, { 'GainP.k#Value': '0.02' }), job(5, {}), now)).toEqual({
            differences: [{ path: 'GainP.k#Value', value: '0.02', latest: '0.0264249' }], more: false,
        });
    });

    it('the latest run may be the one that differs from the model (unsaved edits, a later save)', () => {
        expect(differencesFromLatest(job(3, {}), job(5, { 'Sub$Spring.k': '2e5' }), now).differences)
            .toEqual([{ path: 'Sub$Spring.k', value: '1e5', latest: '2e5' }]);
    });

    it('values both runs used alike are no difference, whatever the model says now', () => {
        const found = differencesFromLatest(job(3, { mass: '12', 'Sub.d': '3' }), job(5, { mass: '12', 'Sub.d': '4' }), now);
        expect(found.differences).toEqual([{ path: 'Sub.d', value: '3', latest: '4' }]);
    });

    it('a parameter the model no longer has reads as none where a run did not use it', () => {
        expect(differencesFromLatest(job(3, { 'Damper.b': '100' }), job(5, {}), now).differences)
            .toEqual([{ path: 'Damper.b', value: '100', latest: null }]);
    });

    it('the latest run differs from itself in nothing', () => {
        const latest = job(5, { mass: '12' }, true);
        expect(differencesFromLatest(latest, latest, now)).toEqual({ differences: [], more: false });
    });

    it('a list the server cut short, of either run, may hide more differences', () => {
        expect(differencesFromLatest(job(3, { mass: '1' }, true), job(5, {}), now).more).toBe(true);
        expect(differencesFromLatest(job(3, { mass: '1' }), job(5, {}, true), now).more).toBe(true);
    });
});

describe('differencesText', () => {
    it('one line per parameter, named as a Hopsan user types it', () => {
        expect(differencesText({ differences: [{ path: 'GainP.k#Value', value: '0.02', latest: '0.0264249' }, { path: 'Damper.b', value: '100', latest: null }], more: false }))
            .toBe('Differs from the latest run in:\nGainP.k: 0.02 (latest 0.0264249)\nDamper.b: 100 (latest none)');
    });

    it('says when nothing differs, and when the server did not list everything', () => {
        expect(differencesText({ differences: [], more: false })).toBe('Same parameters as the latest run');
        expect(differencesText({ differences: [], more: true })).toMatch(/cut the list short/);
        expect(differencesText({ differences: [{ path: 'mass', value: '1', latest: '2' }], more: true }))
            .toBe('Differs from the latest run in:\nmass: 1 (latest 2)\nand more');
    });

    it('lists at most maxLines differences and counts the rest', () => {
        const differences = Array.from({ length: 5 }, (_, i) => ({ path: `G${i}.k`, value: '1', latest: '2' }));
        const lines = differencesText({ differences, more: false }, 3).split('\n');
        expect(lines).toEqual(['Differs from the latest run in:', 'G0.k: 1 (latest 2)', 'G1.k: 1 (latest 2)', 'G2.k: 1 (latest 2)', 'and 2 more']);
        expect(differencesText({ differences, more: true }, 3).split('\n').at(-1)).toBe('and 2+ more');
    });
});
