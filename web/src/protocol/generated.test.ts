import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
// @ts-expect-error plain ES module script without types
import { generateTypes, generatedFile } from '../../scripts/generateTypes.mjs';

describe('generated protocol types', () => {
    it('are up to date with protocol/*.schema.json (run npm run gen:types)', async () => {
        const fresh: string = await generateTypes();
        expect(readFileSync(generatedFile, 'utf8')).toBe(fresh);
    }, 30000);
});
