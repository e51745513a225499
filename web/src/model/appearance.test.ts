import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
// @ts-expect-error plain ES module script without types
import { extractAppearance, extractFile } from '../../scripts/extractAppearance.mjs';
import { appearanceOf, displayNameOf, libraryOf } from './appearance';

describe('appearance facts', () => {
    it('the committed extract is up to date with ../shared/reference/appearance.json (run npm run gen:appearance)', () => {
        // throws when ../shared is missing
        expect(readFileSync(extractFile, 'utf8')).toBe(extractAppearance());
    });

    it('names and folders read as in Hopsan', () => {
        expect(displayNameOf('SignalSink')).toBe('Scope');
        expect(libraryOf('SignalSink')).toBe('Signal/Sources&Sinks');
        expect(libraryOf('Subsystem')).toBe('Subsystem');
        expect(appearanceOf('SignalSineWave')?.ports.out).toEqual([1, 0.5, 0]);
        expect(displayNameOf('NoSuchType')).toBe('NoSuchType');
    });
});
