// What the server warns the teacher of about their assignment (protocol AssignmentWarning):
// shown above the assignment and in its form, each sentence with what to do about it, so an
// assignment students cannot pass is noticed before they start.
import { h } from '../ui/dom';
import type { AssignmentWarning } from '../protocol/types';
import type { Assignment } from './types';

/** An assignment as its teacher reads it: the server adds the warnings for them only. */
export type TeacherAssignment = Assignment & { warnings?: AssignmentWarning[] };

const ADVICE: Record<AssignmentWarning['code'], string> = {
    template_outside_bounds: 'Students start outside the bounds: change the bounds, or save the template with a value inside them.',
    solution_outside_bounds: 'No student can reach the solution within these bounds: widen them or change the solution.',
    template_lacks_parameter: 'Check the name (Component.parameter) against the template.',
    solution_lacks_parameter: 'Check the name (Component.parameter) against the solution.',
    solution_fails_check: 'Even the solution would not get these points: loosen the check or correct the solution.',
};

/** The warning in words: the server's sentence and what the teacher can do. */
export function warningText(warning: AssignmentWarning): string {
    const advice = ADVICE[warning.code];
    return advice ? `${warning.message} ${advice}` : warning.message;
}

/** The warnings of the assignment, or null when there are none (or the caller is not its teacher). */
export function assignmentWarnings(assignment: TeacherAssignment): HTMLElement | null {
    const warnings = assignment.warnings ?? [];
    if (warnings.length === 0) return null;
    return h('div', { class: 'notice assignment-warnings', role: 'status', 'data-testid': 'assignment-warnings' },
        h('strong', {}, warnings.length === 1 ? 'Check this before students start:' : `Check these ${warnings.length} things before students start:`),
        h('ul', {}, ...warnings.map((w) => h('li', { 'data-code': w.code }, warningText(w)))));
}
