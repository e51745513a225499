// App entry: hash routes #/login, #/models, #/model/<id>[?assignment=<id>][&path=<subsystems>], #/account,
// #/classes, #/class/<id>, #/assignment/<id>, #/watch/<live session id>?class=<id>, #/admin/lti,
// #/lti-place/<key> (placing an assignment in a learning platform's course); the ends of a sign-in,
// #/signed-in/<key>[/class/<id>|/assignment/<id>|/place/<key>] and #/sign-in-failed/<reason>.
// Only the hash routes and absolute asset paths: the same index.html also serves as the LTI launch page.
// First: the modules below may touch storage as they load (storageFallback.ts).
import './app/installStorageFallback';
import 'uplot/dist/uPlot.min.css';
import './styles.css';
import { Session } from './app/Session';
import { renderLogin } from './views/LoginView';
import { renderModelList } from './views/ModelListView';
import { renderEditor, type BackLink, type EditorPage } from './views/EditorView';
import { renderAccounts } from './views/AccountsView';
import { renderLtiPlatforms } from './views/LtiPlatformsView';
import { renderClassList } from './labs/ClassListView';
import { renderClass } from './labs/ClassView';
import { allowedText, renderAssignment } from './labs/AssignmentView';
import type { LabPage } from './labs/LabPage';
import { renderLtiPlace } from './labs/LtiPlaceView';
import { renderWatch } from './live/WatchView';
import { h } from './ui/dom';
import { parseModelRoute, sameModel } from './app/modelRoute';
import { finishSignIn, parseSignInEnd } from './app/signInRoute';

const session = new Session();
const app = document.getElementById('app')!;
const page = h('div', { class: 'page' });
const topbar = h('header', { class: 'topbar' });
app.replaceChildren(topbar, page);

let editor: EditorPage | null = null;
let labPage: LabPage | null = null;
let currentHash = '';
let ignoreNextHash = false;

function navigate(hash: string, replace = false): void {
    if (replace) {
        // same page, new address (e.g. saved as a copy): no reload of the view
        history.replaceState(null, '', hash);
        currentHash = hash;
        return;
    }
    location.hash = hash;
}

function renderTopbar(): void {
    const user = session.user;
    topbar.replaceChildren(
        h('a', { href: '#/models', class: 'brand' }, 'tlmhub'),
        user ? h('nav', { class: 'topnav', 'aria-label': 'Main' },
            h('a', { href: '#/models', 'data-testid': 'nav-models' }, 'Models'),
            h('a', { href: '#/classes', 'data-testid': 'nav-classes' }, 'Classes')) : '',
        h('span', { class: 'spacer' }),
        user ? h('a', { href: '#/account', class: 'user', 'data-testid': 'user', title: 'Your account' }, `${user.username} (${user.role})`) : '',
        user ? h('button', {
            onclick: async () => {
                if (editor?.dirty() && !confirm('Discard unsaved changes?')) return;
                await session.logout().catch(() => undefined);
                location.hash = '#/login';
            },
        }, 'Log out') : '');
}

async function route(): Promise<void> {
    if (ignoreNextHash) {
        ignoreNextHash = false;
        return;
    }
    const hash = location.hash || '#/models';
    const modelRoute = parseModelRoute(hash);
    if (editor && sameModel(modelRoute, parseModelRoute(currentHash))) {
        // another level of the open model (a subsystem entered, Back or Forward): stay in the editor
        currentHash = hash;
        editor.showPath(modelRoute!.path);
        return;
    }
    if (editor && hash !== currentHash) {
        if (editor.dirty() && !confirm('The model has unsaved changes. Leave anyway?')) {
            ignoreNextHash = true;
            location.hash = currentHash;
            return;
        }
        editor.dispose();
        editor = null;
    }
    labPage?.dispose();
    labPage = null;
    currentHash = hash;
    // The end of a sign-in through a provider or a learning platform's launch (signInRoute.ts):
    // the one-time key, taken out of the history at once, then on to the page named or the models.
    const signInEnd = parseSignInEnd(hash);
    if (signInEnd) {
        await finishSignIn(signInEnd, {
            replaceAddress: (to) => {
                history.replaceState(null, '', to);
                currentHash = to;
            },
            collect: (key) => session.collectSignIn(key),
            go: (to) => { location.hash = to; },
            showLogin: (failure) => renderLogin(page, session, () => { location.hash = '#/models'; }, failure),
        });
        return;
    }
    if (!session.user && !(await session.restore()) && hash !== '#/login') {
        location.hash = '#/login';
        return;
    }
    renderTopbar();
    const lab = /^#\/(class|assignment)\/(\d+)$/.exec(hash);
    const watch = /^#\/watch\/(\d+)(?:\?class=(\d+))?$/.exec(hash);
    const place = /^#\/lti-place\/([A-Za-z0-9_-]+)$/.exec(hash);
    if (hash === '#/login') {
        renderLogin(page, session, () => { location.hash = '#/models'; });
    } else if (hash === '#/account') {
        renderAccounts(page, session, () => { void session.logout().catch(() => undefined).finally(() => { location.hash = '#/login'; }); });
    } else if (hash === '#/admin/lti') {
        renderLtiPlatforms(page, session);
    } else if (modelRoute) {
        let back: BackLink | undefined;
        if (modelRoute.assignment !== undefined) {
            // an assignment's copy: back to the assignment, with what the student may change
            const assignment = await session.labs.getAssignment(modelRoute.assignment).catch(() => null);
            back = { href: `#/assignment/${modelRoute.assignment}`, label: assignment?.title ?? 'Assignment',
                note: assignment ? `Assignment copy. ${allowedText(assignment)}` : undefined };
        }
        const opened = await renderEditor(page, session, modelRoute.id, navigate, back, modelRoute.path);
        if (currentHash === hash) {
            editor = opened;
        } else {
            // Left while the model was opening: this editor is not the page any more.
            opened.dispose();
            await route();
        }
    } else if (watch) {
        // a live session shared with a class, watched read-only (it ends with the page)
        const back = watch[2] ? { href: `#/class/${watch[2]}`, label: 'Class' } : { href: '#/classes', label: 'Classes' };
        const shown = await renderWatch(page, session, Number(watch[1]), back);
        if (currentHash === hash) labPage = shown;
        else shown.dispose();
    } else if (place) {
        await renderLtiPlace(page, session, place[1]);
    } else if (hash === '#/classes') {
        await renderClassList(page, session);
    } else if (lab) {
        const shown = lab[1] === 'class'
            ? await renderClass(page, session, Number(lab[2]))
            : await renderAssignment(page, session, Number(lab[2]));
        if (currentHash === hash) labPage = shown;
        else shown.dispose();
    } else {
        await renderModelList(page, session, (id) => { location.hash = `#/model/${id}`; });
    }
}

window.addEventListener('hashchange', () => void route());
void route();
