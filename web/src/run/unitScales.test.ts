import { existsSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { UNIT_SCALES } from './unitScales';

const reference = resolve(process.cwd(), '../../shared/reference/units.json');

interface ReferenceUnit { name: string; scale: number; offset?: number }
interface Reference { quantities: { quantity: string; base: string; units: ReferenceUnit[] }[] }

describe('unit scales', () => {
    it('hold exactly the quantities, base units, scales and offsets of ../shared/reference/units.json', () => {
        if (!existsSync(reference)) throw new Error(`the unit reference is missing: ${reference}`);
        const facts = JSON.parse(readFileSync(reference, 'utf8')) as Reference;
        // the reference also records how Hopsan writes each number (scaleExpression): not needed here
        const expected = facts.quantities.map((q) => ({
            quantity: q.quantity, base: q.base,
            units: q.units.map((u) => (u.offset === undefined ? { name: u.name, scale: u.scale } : { name: u.name, scale: u.scale, offset: u.offset })),
        }));
        expect(UNIT_SCALES).toEqual(expected);
    });
});
