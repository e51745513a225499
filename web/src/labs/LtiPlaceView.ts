// Placing an assignment in a learning platform's course (#/lti-place/KEY): a teacher who adds
// tlmhub to a course from Moodle or Canvas (LTI Deep Linking) is signed in and sent here with a
// key for that one placement, which names the course's class. The page lists the class's
// assignments; the one picked is answered with a signed deep-linking response, which the
// browser posts to the platform's return address as form field JWT: the app is left there and
// the platform shows its own page. The key lasts 10 minutes and places once.
import { errorText, h } from '../ui/dom';
import { ApiError } from '../api/ApiError';
import type { Session } from '../app/Session';
import type { LtiDeepLink, LtiDeepLinkAnswer } from '../protocol/types';
import type { Assignment, LabClass } from './types';
import { formatTime } from './format';
import { errorPage, section } from './LabPage';

export const EXPIRED_TEXT = 'This placement has expired or was used; add the activity again from the course.';

/** The placement's refusal in words: a 404 is a key used, too old or another teacher's. */
function placementError(e: unknown): string {
    return e instanceof ApiError && e.status === 404 ? EXPIRED_TEXT : errorText(e);
}

/** Posts the signed answer to the platform as a form would (the platform expects a top-level form post). */
export function postToPlatform(answer: LtiDeepLinkAnswer): void {
    // the address comes from the platform's launch; anything but a web address is not sent to
    if (!/^https?:\/\//i.test(answer.return_url)) throw new Error('The platform gave no web address to return to.');
    const form = h('form', { method: 'post', action: answer.return_url, hidden: true },
        h('input', { type: 'hidden', name: 'JWT', value: answer.jwt }));
    document.body.append(form);
    form.submit();
}

export async function renderLtiPlace(root: HTMLElement, session: Session, key: string): Promise<void> {
    root.replaceChildren(h('main', { class: 'loading' }, h('p', { class: 'muted' }, 'Opening the placement…')));
    const failed = (text: string) =>
        root.replaceChildren(errorPage('Cannot place an assignment', text, { href: '#/classes', label: 'Go to the classes' }));
    let link: LtiDeepLink;
    let assignments: Assignment[];
    try {
        link = await session.rest.ltiDeepLink(key);
    } catch (e) {
        failed(placementError(e));
        return;
    }
    try {
        assignments = await session.labs.listAssignments(link.class_id);
    } catch (e) {
        failed(errorText(e));
        return;
    }
    // the class's name for the heading only: without it the page still works
    const theClass: LabClass | null = await session.labs.getClass(link.class_id).catch(() => null);
    const message = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'lti-place-error' });
    const status = h('p', { class: 'muted', role: 'status', 'data-testid': 'lti-place-status' });
    const buttons: HTMLButtonElement[] = [];
    const place = async (assignment: Assignment, button: HTMLButtonElement) => {
        message.textContent = '';
        for (const b of buttons) b.disabled = true;
        const label = button.textContent;
        button.textContent = 'Placing…';
        try {
            postToPlatform(await session.rest.placeLtiDeepLink(key, assignment.id));
            status.textContent = `Sending "${assignment.title}" to ${link.platform}…`;
        } catch (e) {
            message.textContent = placementError(e);
            button.textContent = label;
            for (const b of buttons) b.disabled = false;
        }
    };

    const rows = assignments.map((a) => {
        const button = h('button', { type: 'button', class: 'primary', 'aria-label': `Place ${a.title} in the course` }, 'Place in course');
        button.addEventListener('click', () => void place(a, button));
        buttons.push(button);
        return h('tr', { dataset: { assignmentId: String(a.id) } },
            h('td', {}, h('a', { href: `#/assignment/${a.id}`, class: 'assignment-link' }, a.title)),
            h('td', {}, formatTime(a.opens_at)),
            h('td', {}, a.due_at ? formatTime(a.due_at) : 'none'),
            h('td', {}, button));
    });
    const expires = h('p', { class: 'muted', 'data-testid': 'lti-place-expires' }, `This link expires at ${formatTime(link.expires_at)}.`);
    const list = assignments.length === 0
        ? h('div', { 'data-testid': 'lti-place-empty' },
            h('p', {}, 'This class has no assignments yet. Create one on ',
                h('a', { href: `#/class/${link.class_id}`, 'data-testid': 'lti-place-class' }, 'the class page'),
                ', then come back to this page (the browser\'s Back button) to place it.'),
            expires)
        : h('div', {},
            h('p', { class: 'muted' }, `The placed link opens the assignment in tlmhub, and each hand-in's score goes to the grade book of ${link.platform}.`),
            expires,
            h('table', { class: 'model-table', 'data-testid': 'lti-place-table' },
                h('thead', {}, h('tr', {}, h('th', {}, 'Assignment'), h('th', {}, 'Opens'), h('th', {}, 'Due'),
                    h('th', {}, h('span', { class: 'visually-hidden' }, 'Place')))),
                h('tbody', {}, ...rows)));

    root.replaceChildren(h('main', { class: 'model-list-page lab-page', 'data-testid': 'lti-place-page' },
        h('div', { class: 'lab-title' }, h('h1', {}, 'Place an assignment in the course')),
        h('p', {}, 'Choose the assignment of ', theClass ? h('strong', {}, theClass.name) : 'the course\'s class',
            ` that the course in ${link.platform} links to.`),
        message,
        section('Assignments', 'lti-place-assignments', list),
        status));
}
