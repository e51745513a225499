// The end of a sign-in (a provider's, or a learning platform's launch at /lti/#/signed-in/...):
// the key out of the history first, then the login, then the page the launch named.
import { describe, expect, it } from 'vitest';
import { finishSignIn, parseSignInEnd, type SignInEndSteps } from './signInRoute';

function recorder(collect: (key: string) => Promise<unknown> = async () => undefined) {
    const steps: string[] = [];
    const handlers: SignInEndSteps = {
        replaceAddress: (hash) => steps.push(`replace ${hash}`),
        collect: async (key) => { steps.push(`collect ${key}`); return collect(key); },
        go: (hash) => steps.push(`go ${hash}`),
        showLogin: (failure) => steps.push(`login ${failure}`),
    };
    return { steps, handlers };
}

describe('sign-in end', () => {
    it('reads the key and where a launch continues', () => {
        expect(parseSignInEnd('#/signed-in/Zk9m_W-J4c2')).toEqual({ kind: 'signed-in', key: 'Zk9m_W-J4c2', next: '#/models' });
        expect(parseSignInEnd('#/signed-in/KEY/class/12')).toEqual({ kind: 'signed-in', key: 'KEY', next: '#/class/12' });
        expect(parseSignInEnd('#/signed-in/KEY/assignment/7')).toEqual({ kind: 'signed-in', key: 'KEY', next: '#/assignment/7' });
        expect(parseSignInEnd('#/sign-in-failed/no_account')).toEqual({ kind: 'failed', reason: 'no_account' });
    });

    it('is no sign-in end for other addresses or continuations it does not know', () => {
        for (const hash of ['#/models', '#/login', '#/signed-in/', '#/signed-in/KEY/model/3', '#/signed-in/KEY/class/',
            '#/signed-in/KEY/class/12/x', '#/signed-in/KEY/class/-1', '#/signed-in/K.E.Y', '#/signed-in/KEY/assignment/7?x=1',
            '#/signed-in/KEY/place/', '#/signed-in/KEY/place/D.L', '#/signed-in/KEY/place/DL/x', '#/signed-in/KEY/place/DL?x=1',
            '#/signed-in/KEY/class/12/place/DL']) {
            expect(parseSignInEnd(hash), hash).toBeNull();
        }
    });

    it('continues a deep-linking launch to the placement page with its key', () => {
        expect(parseSignInEnd('#/signed-in/KEY/place/Dl_k-9x')).toEqual({ kind: 'signed-in', key: 'KEY', next: '#/lti-place/Dl_k-9x' });
    });

    it('takes the key out of the history before trading it, then goes on to the placement page', async () => {
        const { steps, handlers } = recorder();
        await finishSignIn(parseSignInEnd('#/signed-in/KEY/place/DLKEY')!, handlers);
        expect(steps).toEqual(['replace #/login', 'collect KEY', 'go #/lti-place/DLKEY']);
    });

    it('takes the key out of the history before trading it, then goes on to the page named', async () => {
        const { steps, handlers } = recorder();
        await finishSignIn(parseSignInEnd('#/signed-in/KEY/class/12')!, handlers);
        expect(steps).toEqual(['replace #/login', 'collect KEY', 'go #/class/12']);
    });

    it('replaces the address at once, before the login is asked for', () => {
        const { steps, handlers } = recorder(() => new Promise(() => undefined));
        void finishSignIn(parseSignInEnd('#/signed-in/KEY/assignment/7')!, handlers);
        expect(steps).toEqual(['replace #/login', 'collect KEY']);
    });

    it('without a continuation goes to the models; a spent key shows the login page', async () => {
        const plain = recorder();
        await finishSignIn(parseSignInEnd('#/signed-in/KEY')!, plain.handlers);
        expect(plain.steps).toEqual(['replace #/login', 'collect KEY', 'go #/models']);

        const spent = recorder(async () => { throw new Error('unauthorized'); });
        await finishSignIn(parseSignInEnd('#/signed-in/KEY/class/12')!, spent.handlers);
        expect(spent.steps).toEqual(['replace #/login', 'collect KEY', 'login expired']);

        const refused = recorder();
        await finishSignIn(parseSignInEnd('#/sign-in-failed/no_account')!, refused.handlers);
        expect(refused.steps).toEqual(['replace #/login', 'login no_account']);
    });
});
