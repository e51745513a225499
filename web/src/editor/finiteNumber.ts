// A number parameter's value must come out finite, as the server checks it: a plain number
// that overflows ("1e400") or nan/inf spelled out is refused in the panel before it is sent.
// Expressions and system-parameter names are left to the server, which evaluates them.
import type { Param } from '../protocol/types';

const NUMBER_LITERAL = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;
const NOT_FINITE_WORD = /^[+-]?(nan|inf|infinity)$/i;

/** The refusal of `text` for the number parameter `name` ("Mass.m: '1e400' is not a finite number"), or null. */
export function notFiniteError(name: string, type: Param['type'], text: string): string | null {
    if (type !== 'double' && type !== 'integer') return null;
    const value = text.trim();
    const notFinite = NOT_FINITE_WORD.test(value) || (NUMBER_LITERAL.test(value) && !Number.isFinite(Number(value)));
    return notFinite ? `${name}: '${value}' is not a finite number` : null;
}
