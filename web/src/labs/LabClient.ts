// The lab calls of the REST API (docs/labs.md), on the app's RestClient: its bearer token,
// its errors (ApiError with the server's code) and its 401 handling.
import type { RestClient } from '../api/RestClient';
import type { LtiScoreInfo, LtiScoreList } from '../protocol/types';
import type {
    Assignment, AssignmentInput, Check, ClassRole, Copy, DashboardRow, Gradebook, HandIn, HandInComment,
    ImportedAccount, LabClass, Overlay, PretestPending, PretestResult, SharedLiveSession,
} from './types';

const id = (n: number) => encodeURIComponent(String(n));

const isPending = (reply: PretestResult | PretestPending): reply is PretestPending =>
    !('checks' in reply) && 'location' in reply;

export class LabClient {
    constructor(private readonly rest: RestClient) {}

    // ---- classes
    listClasses(): Promise<LabClass[]> {
        return this.rest.call<{ classes: LabClass[] }>('GET', '/classes').then((r) => r.classes);
    }
    createClass(name: string): Promise<LabClass> { return this.rest.call('POST', '/classes', { name }); }
    getClass(classId: number): Promise<LabClass> { return this.rest.call('GET', `/classes/${id(classId)}`); }
    updateClass(classId: number, change: { name?: string; archived?: boolean }): Promise<LabClass> {
        return this.rest.call('PATCH', `/classes/${id(classId)}`, change);
    }
    deleteClass(classId: number): Promise<void> { return this.rest.call('DELETE', `/classes/${id(classId)}`); }
    join(code: string): Promise<LabClass> { return this.rest.call('POST', '/classes/join', { code }); }
    /** The live sessions shared with the class on the server answering (live.share). */
    sharedLiveSessions(classId: number): Promise<SharedLiveSession[]> {
        return this.rest.call<{ sessions: SharedLiveSession[] }>('GET', `/classes/${id(classId)}/live`).then((r) => r.sessions);
    }
    /** One user name per line (the first column; a header `username` is skipped). */
    importAccounts(classId: number, usernames: string[]): Promise<ImportedAccount[]> {
        const csv = usernames.map((u) => u.trim()).filter((u) => u !== '').join('\n') + '\n';
        return this.rest.call<{ accounts: ImportedAccount[] }>('POST', `/classes/${id(classId)}/import`, csv, 'text/csv')
            .then((r) => r.accounts);
    }
    setMember(classId: number, userId: number, role: ClassRole): Promise<unknown> {
        return this.rest.call('PUT', `/classes/${id(classId)}/members/${id(userId)}`, { role });
    }
    removeMember(classId: number, userId: number): Promise<void> {
        return this.rest.call('DELETE', `/classes/${id(classId)}/members/${id(userId)}`);
    }
    gradebookCsv(classId: number): Promise<string> {
        return this.rest.call('GET', `/classes/${id(classId)}/gradebook?format=csv`, undefined, undefined, 'text/csv');
    }
    gradebook(classId: number): Promise<Gradebook> {
        return this.rest.call('GET', `/classes/${id(classId)}/gradebook?format=json`);
    }

    // ---- assignments
    listAssignments(classId: number): Promise<Assignment[]> {
        return this.rest.call<{ assignments: Assignment[] }>('GET', `/classes/${id(classId)}/assignments`)
            .then((r) => r.assignments);
    }
    createAssignment(classId: number, input: AssignmentInput): Promise<Assignment> {
        return this.rest.call('POST', `/classes/${id(classId)}/assignments`, input);
    }
    getAssignment(assignmentId: number): Promise<Assignment> {
        return this.rest.call('GET', `/assignments/${id(assignmentId)}`);
    }
    updateAssignment(assignmentId: number, change: AssignmentInput): Promise<Assignment> {
        return this.rest.call('PATCH', `/assignments/${id(assignmentId)}`, change);
    }
    deleteAssignment(assignmentId: number): Promise<void> {
        return this.rest.call('DELETE', `/assignments/${id(assignmentId)}`);
    }
    getChecks(assignmentId: number): Promise<Check[]> {
        return this.rest.call<{ checks: Check[] }>('GET', `/assignments/${id(assignmentId)}/checks`).then((r) => r.checks);
    }
    /** Runs the solution and stores the reference result with the checks. */
    putChecks(assignmentId: number, checks: Check[]): Promise<unknown> {
        return this.rest.call('PUT', `/assignments/${id(assignmentId)}/checks`, { checks });
    }
    open(assignmentId: number): Promise<Copy> {
        return this.rest.call<{ copy: Copy }>('POST', `/assignments/${id(assignmentId)}/open`).then((r) => r.copy);
    }
    reset(assignmentId: number): Promise<Copy> {
        return this.rest.call<{ copy: Copy }>('POST', `/assignments/${id(assignmentId)}/reset`).then((r) => r.copy);
    }
    /**
     * Runs the pretests. The run goes through the server's job queue; the server waits for it
     * up to a minute (--lab-wait-seconds), then answers 202 with the run's state and where to
     * ask again: this asks there every `pollMs` (telling `onWaiting` the state) until the
     * outcome is in.
     */
    async pretest(assignmentId: number, onWaiting?: (state: string) => void, pollMs = 1000): Promise<PretestResult> {
        let reply = await this.rest.call<PretestResult | PretestPending>('POST', `/assignments/${id(assignmentId)}/pretest`);
        while (isPending(reply)) {
            onWaiting?.(reply.state);
            await new Promise((resolve) => setTimeout(resolve, pollMs));
            reply = await this.rest.call<PretestResult | PretestPending>(
                'GET', `/assignments/${id(assignmentId)}/pretests/${id(reply.job_id)}`);
        }
        return reply;
    }
    handIn(assignmentId: number): Promise<HandIn> {
        return this.rest.call('POST', `/assignments/${id(assignmentId)}/handin`);
    }
    /** Newest first; a student gets their own, staff everyone's (or one student's). */
    handIns(assignmentId: number, studentId?: number): Promise<HandIn[]> {
        const query = studentId === undefined ? '' : `?student=${id(studentId)}`;
        return this.rest.call<{ handins: HandIn[] }>('GET', `/assignments/${id(assignmentId)}/handins${query}`)
            .then((r) => r.handins);
    }
    dashboard(assignmentId: number): Promise<DashboardRow[]> {
        return this.rest.call<{ students: DashboardRow[] }>('GET', `/assignments/${id(assignmentId)}/dashboard`)
            .then((r) => r.students);
    }
    overlay(assignmentId: number, variable: string, points?: number): Promise<Overlay> {
        const query = `variable=${encodeURIComponent(variable)}${points === undefined ? '' : `&points=${id(points)}`}`;
        return this.rest.call('GET', `/assignments/${id(assignmentId)}/overlay?${query}`);
    }
    /** The scores on their way to learning platforms' grade books, newest first (staff). */
    ltiScores(assignmentId: number): Promise<LtiScoreInfo[]> {
        return this.rest.call<LtiScoreList>('GET', `/assignments/${id(assignmentId)}/lti-scores`).then((r) => r.scores);
    }

    // ---- hand-ins
    getHandIn(handInId: number): Promise<HandIn> { return this.rest.call('GET', `/handins/${id(handInId)}`); }
    handInModel(handInId: number): Promise<string> {
        return this.rest.call('GET', `/handins/${id(handInId)}/model`, undefined, undefined, 'application/xml');
    }
    comments(handInId: number): Promise<HandInComment[]> {
        return this.rest.call<{ comments: HandInComment[] }>('GET', `/handins/${id(handInId)}/comments`).then((r) => r.comments);
    }
    addComment(handInId: number, text: string): Promise<HandInComment> {
        return this.rest.call('POST', `/handins/${id(handInId)}/comments`, { text });
    }
    /** null clears the grade. */
    setGrade(handInId: number, grade: number | null): Promise<HandIn> {
        return this.rest.call('PUT', `/handins/${id(handInId)}/grade`, { grade });
    }
}
