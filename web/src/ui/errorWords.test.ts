import { describe, expect, it } from 'vitest';
import { inWords } from './errorWords';
import { errorText } from './dom';
import { ApiError } from '../api/ApiError';

describe('server messages in words', () => {
    it('request validation paths become sentences about the field', () => {
        expect(inWords('body.password: must be at least 8 characters long')).toBe('The password must be at least 8 characters long.');
        expect(inWords('body.new_password: must be at least 8 characters long')).toBe('The new password must be at least 8 characters long.');
        expect(inWords('body.username: does not match the pattern "^[A-Za-z0-9_.-]{1,64}$"'))
            .toBe('The user name may only use letters, digits, dots, dashes and underscores (at most 64).');
        expect(inWords('body.title: must be at least 1 characters long')).toBe('The title must not be empty.');
        expect(inWords('body: missing required property "password"')).toBe('The password is missing.');
        expect(inWords('body.log_samples: must be >= 1, got 0')).toBe('The number of logged samples must be at least 1 (not 0).');
        expect(inWords('message.pose.x: expected number, got string')).toBe('The x must be a number, not text.');
        expect(inWords('body.role: expected one of ["user","teacher","admin"], got "boss"')).toBe('The role must be user, teacher or admin, not "boss".');
        expect(inWords('body.extra: unknown property')).toBe('The extra is not a field this form takes.');
    });

    it('a list item is named by its place, a server reason gets its field names in words', () => {
        expect(inWords('body.parameters[1].min: expected number, got string')).toBe('The minimum must be a number, not text (in parameter 2).');
        expect(inWords('body.due_at: is before opens_at')).toBe('The due time is before the opening time.');
    });

    it('node types in a refused connection are named in words', () => {
        expect(inWords('cannot connect Step.out to 4_3_Servo_Valve.PT: node types differ (NodeSignal vs NodeHydraulic)'))
            .toBe('Cannot connect Step.out to 4_3_Servo_Valve.PT: a signal port cannot be joined to a hydraulic port (the node types differ).');
        expect(inWords('cannot connect A.P1 to B.P1: node types differ (NodeElectric vs NodeMechanicRotational)'))
            .toBe('Cannot connect A.P1 to B.P1: an electric port cannot be joined to a mechanic rotational port (the node types differ).');
    });

    it('a message already in words passes unchanged', () => {
        expect(inWords('Model not found')).toBe('Model not found');
        expect(inWords('cannot connect Gain.out to Step.out: a signal node can have only one write port'))
            .toBe('cannot connect Gain.out to Step.out: a signal node can have only one write port');
    });

    it('errorText, which every view shows errors with, gives the words', () => {
        expect(errorText(new ApiError('bad_request', 'body.password: must be at least 8 characters long', 400)))
            .toBe('The password must be at least 8 characters long.');
        expect(errorText('plain')).toBe('plain');
    });
});
