import { describe, expect, it } from 'vitest';
import { shareableClasses } from './ShareDialog';
import type { LabClass } from '../labs/types';

const cls = (id: number, name: string, role: LabClass['role'], archived = false): LabClass =>
    ({ id, name, role, archived, owner: { id: 1, username: 't' }, created_at: 0 });

describe('shareableClasses', () => {
    it('offers the classes the user teaches, not archived ones, by name', () => {
        const classes = [cls(1, 'Zeta', 'teacher'), cls(2, 'Alpha', 'teacher'), cls(3, 'Taken', 'student'),
            cls(4, 'Helped', 'assistant'), cls(5, 'Old', 'teacher', true)];
        expect(shareableClasses(classes).map((c) => c.id)).toEqual([2, 1]);
    });
});
