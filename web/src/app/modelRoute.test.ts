import { describe, expect, it } from 'vitest';
import { modelRouteHash, parseModelRoute, sameModel } from './modelRoute';

describe('model route', () => {
    it('reads and writes the subsystem path beside the assignment', () => {
        expect(parseModelRoute('#/model/12?path=Sub1/Inner')).toEqual({ id: 12, path: ['Sub1', 'Inner'] });
        expect(parseModelRoute('#/model/12?assignment=3&path=Sub1')).toEqual({ id: 12, assignment: 3, path: ['Sub1'] });
        expect(parseModelRoute('#/model/12')).toEqual({ id: 12, path: [] });
        expect(modelRouteHash({ id: 12, assignment: 3, path: ['Sub1', 'Inner'] })).toBe('#/model/12?assignment=3&path=Sub1/Inner');
        expect(modelRouteHash({ id: 12, path: [] })).toBe('#/model/12');
        expect(parseModelRoute('#/models')).toBeNull();
    });

    it('different levels of one model are the same model', () => {
        expect(sameModel(parseModelRoute('#/model/12?path=A'), parseModelRoute('#/model/12'))).toBe(true);
        expect(sameModel(parseModelRoute('#/model/12?assignment=1'), parseModelRoute('#/model/12'))).toBe(false);
    });
});
