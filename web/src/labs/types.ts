// The teaching labs as the REST API describes them (docs/labs.md): classes, assignments,
// copies, checks, hand-ins, comments, the dashboard and the overlay plot. The generated
// protocol types do not hold these; they follow docs/labs.md field by field.

/** Someone named in a reply: a class's owner, a student, a comment's author. */
export interface UserRef { id: number; username: string }

/** A member's role in one class (not the server role of the account). */
export type ClassRole = 'teacher' | 'assistant' | 'student';

export interface ClassMember {
    id: number;
    username: string;
    role: ClassRole;
    joined_at?: number;
}

export interface LabClass {
    id: number;
    name: string;
    owner: UserRef;
    /** staff only */
    join_code?: string;
    archived: boolean;
    created_at: number;
    /** the caller's role in the class (the server gives an administrator `teacher` in every class) */
    role?: ClassRole | null;
    /** staff only, in GET /classes/{id} */
    members?: ClassMember[];
}

export interface ImportedAccount {
    username: string;
    /** the account (absent when it could not be created) */
    id?: number;
    /** only for a new account, only in this reply */
    password?: string;
    created: boolean;
    /** why the account could not be created (e.g. a name the server refuses) */
    error?: string;
}

export type EditMode = 'free' | 'parameters';

/** A parameter a student may change: `Component.param` or a system parameter's name. */
export interface AllowedParameter { name: string; min?: number; max?: number }

export type StudentStatus = 'not_opened' | 'working' | 'ran' | 'handed_in' | 'late';

export interface Copy { model_id: number; template_version: number; outdated: boolean }

export interface Assignment {
    id: number;
    class_id: number;
    title: string;
    instructions: string;
    edit_mode: EditMode;
    parameters: AllowedParameter[];
    opens_at: number;
    /** 0: no deadline */
    due_at: number;
    template_version: number;
    has_solution: boolean;
    created_at: number;
    updated_at: number;
    /** a student's own */
    status?: StudentStatus;
    copy?: Copy | null;
}

/** POST /classes/{id}/assignments, PATCH /assignments/{id}. */
export interface AssignmentInput {
    title?: string;
    instructions?: string;
    template_model_id?: number;
    solution_model_id?: number;
    opens_at?: number;
    due_at?: number;
    edit_mode?: EditMode;
    parameters?: AllowedParameter[];
}

export type ScalarMeasure = 'final' | 'min' | 'max' | 'overshoot' | 'settling_time' | 'rise_time';
export const SCALAR_MEASURES: ScalarMeasure[] = ['final', 'min', 'max', 'overshoot', 'settling_time', 'rise_time'];

export interface CurveCheck { kind: 'curve'; variable: string; tolerance?: number }
export interface ScalarCheck {
    kind: 'scalar';
    variable: string;
    measure: ScalarMeasure;
    min?: number;
    max?: number;
    /** settling_time: ± band of the final value, relative */
    band?: number;
}
export type CheckDefinition = CurveCheck | ScalarCheck;

export interface Check {
    name: string;
    points: number;
    pretest: boolean;
    /** students see the pretests' definitions only; other checks come as name and points */
    definition?: CheckDefinition;
}

export interface CheckOutcome {
    name: string;
    pretest: boolean;
    passed: boolean;
    points: number;
    awarded: number;
    value?: number | null;
    deviation?: number | null;
    worst_time?: number | null;
    message: string;
}

export interface PretestResult { checks: CheckOutcome[]; score: number; max_score: number; job_id?: number }
/** A pretest whose run has not ended yet (202): ask again at `location`. */
export interface PretestPending { job_id: number; state: string; location: string }

export interface HandIn {
    id: number;
    assignment_id: number;
    student: UserRef;
    attempt: number;
    handed_in_at: number;
    late: boolean;
    score: number;
    max_score: number;
    grade: number | null;
    job_id: number | null;
    checks?: CheckOutcome[];
}

export interface HandInComment { id: number; author: UserRef; text: string; created_at: number }

export interface DashboardRow {
    student: UserRef;
    status: StudentStatus;
    copy_model_id: number | null;
    last_run_at: number | null;
    job_id: number | null;
    handins: number;
    handed_in_at: number | null;
    late: boolean;
    score: number | null;
    max_score: number | null;
    grade: number | null;
    /** the latest hand-in (the server sends it; docs/labs.md does not list it) */
    handin_id?: number | null;
}

/** GET /classes/{id}/gradebook?format=json: one cell per assignment, in `assignments`' order. */
export interface GradebookCell {
    /** the teacher's grade where set, else the latest hand-in's score; null: not handed in */
    points: number | null;
    late: boolean;
}
export interface Gradebook {
    assignments: { id: number; title: string }[];
    students: { student: UserRef; cells: GradebookCell[] }[];
}

export interface OverlaySeries { student: UserRef; job_id: number; time: number[]; values: number[] }
export interface Overlay { variable: string; series: OverlaySeries[] }

export const STATUS_LABELS: Record<StudentStatus, string> = {
    not_opened: 'not opened',
    working: 'working',
    ran: 'ran',
    handed_in: 'handed in',
    late: 'handed in late',
};

/** Staff of a class: may see every student's work. */
export function isStaff(role: ClassRole | null | undefined, serverRole?: string): boolean {
    return role === 'teacher' || role === 'assistant' || serverRole === 'admin';
}

/** May change the class: its teacher, or an administrator. */
export function isTeacher(role: ClassRole | null | undefined, serverRole?: string): boolean {
    return role === 'teacher' || serverRole === 'admin';
}

/** A live session a teacher shares with the class (GET /classes/{id}/live): members may watch it. */
export interface SharedLiveSession {
    session_id: number;
    model_name: string;
    teacher: { id: number; username: string };
}
