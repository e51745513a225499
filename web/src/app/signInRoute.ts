// The end of a sign-in through a provider or a learning platform's launch: the app is sent to
// #/signed-in/KEY, or #/signed-in/KEY/class/N or #/signed-in/KEY/assignment/N when an LTI
// launch names where to continue (on the server's launch page, another path serving the same
// index.html), #/signed-in/KEY/place/DLKEY after a deep-linking launch (on to #/lti-place/DLKEY,
// where the teacher picks the assignment to place in the course), or to
// #/sign-in-failed/REASON. The one-time key leaves the history at once, before anything else
// happens; it is then traded for a login, and the app goes on to the page named, else the models.

export type SignInEnd =
    | { kind: 'signed-in'; key: string; next: string }
    | { kind: 'failed'; reason: string };

const SIGNED_IN = /^#\/signed-in\/([A-Za-z0-9_-]+)(?:\/(class|assignment)\/(\d+)|\/place\/([A-Za-z0-9_-]+))?$/;
const FAILED = /^#\/sign-in-failed\/([a-z_]+)$/;

/** The sign-in end an address is, or null for any other address. */
export function parseSignInEnd(hash: string): SignInEnd | null {
    const signedIn = SIGNED_IN.exec(hash);
    if (signedIn) {
        const next = signedIn[2] ? `#/${signedIn[2]}/${Number(signedIn[3])}`
            : signedIn[4] ? `#/lti-place/${signedIn[4]}` : '#/models';
        return { kind: 'signed-in', key: signedIn[1], next };
    }
    const failed = FAILED.exec(hash);
    return failed ? { kind: 'failed', reason: failed[1] } : null;
}

export interface SignInEndSteps {
    /** Replaces the address in the history (history.replaceState): the key must not stay there. */
    replaceAddress: (hash: string) => void;
    /** Trades the key for a login (Session.collectSignIn). */
    collect: (key: string) => Promise<unknown>;
    /** Goes on to the page after the sign-in. */
    go: (hash: string) => void;
    /** The login page, with why the sign-in did not succeed. */
    showLogin: (failure: string) => void;
}

/** Finishes a sign-in end (see parseSignInEnd); the address is #/login once the key is out of it. */
export async function finishSignIn(end: SignInEnd, steps: SignInEndSteps): Promise<void> {
    steps.replaceAddress('#/login');
    let failure: string;
    if (end.kind === 'signed-in') {
        try {
            await steps.collect(end.key);
            steps.go(end.next);
            return;
        } catch {
            failure = 'expired';
        }
    } else {
        failure = end.reason;
    }
    steps.showLogin(failure);
}
