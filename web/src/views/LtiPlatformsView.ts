// The administrator's page of learning platforms (#/admin/lti): Moodle, Canvas and other LTI 1.3
// platforms that launch tlmhub from their courses (docs/sign-in.md). It shows the tool's own
// addresses, named as Moodle's "Configure a tool manually" form names them, to copy into the
// platform; the registered platforms, to edit or remove; and the form that registers one with
// the values the platform gave. The form checks what the server checks (LtiPlatformSettings in
// protocol/messages.schema.json) before sending, and shows the server's refusal when it refuses.
import { h, errorText, toast } from '../ui/dom';
import { ApiError } from '../api/ApiError';
import { formatTime } from '../labs/format';
import type { Session } from '../app/Session';
import type { LtiPlatform, LtiPlatformSettings, LtiToolSettings } from '../protocol/types';

export const MAX_DEPLOYMENTS = 100;
const MAX_NAME = 100;
const MAX_URL = 2000;
const MAX_ID = 255;

export type PlatformField = keyof LtiPlatformSettings;
/** The form's texts, as typed. */
export type PlatformInput = Record<PlatformField, string>;
export type PlatformErrors = Partial<Record<PlatformField, string>>;

const FIELDS: PlatformField[] = ['name', 'issuer', 'client_id', 'auth_url', 'token_url', 'jwks_url', 'deployment_ids'];
const URL_FIELDS = new Set<PlatformField>(['issuer', 'auth_url', 'token_url', 'jwks_url']);

interface FieldText { label: string; hint: string; placeholder?: string }

/** Labels, and where Moodle and Canvas show each value. */
const FIELD_TEXT: Record<PlatformField, FieldText> = {
    name: { label: 'Name', hint: 'Shown here only, e.g. the faculty\'s Moodle.' },
    issuer: { label: 'Issuer', hint: 'Moodle: Platform ID. Canvas: https://canvas.instructure.com.', placeholder: 'https://moodle.uni.edu' },
    client_id: { label: 'Client id', hint: 'Moodle: Client ID. Canvas: the developer key\'s id.' },
    auth_url: { label: 'Authentication URL', hint: 'Moodle: Authentication request URL.', placeholder: 'https://moodle.uni.edu/mod/lti/auth.php' },
    token_url: { label: 'Token URL', hint: 'Moodle: Access token URL.', placeholder: 'https://moodle.uni.edu/mod/lti/token.php' },
    jwks_url: { label: 'Keyset URL', hint: 'Moodle: Public keyset URL.', placeholder: 'https://moodle.uni.edu/mod/lti/certs.php' },
    deployment_ids: { label: 'Deployment ids', hint: `Moodle: Deployment ID. Separated by commas or new lines; at most ${MAX_DEPLOYMENTS}.` },
};

/** The deployment ids of the form's text: separated by commas or line breaks, blanks left out. */
export function deploymentIds(text: string): string[] {
    return text.split(/[,\r\n]+/).map((id) => id.trim()).filter((id) => id !== '');
}

// What the server refuses in names shown in lists (server/store/ModelName.cpp): control
// characters, line and paragraph separators, and bidirectional controls.
const HIDDEN_CHARACTERS = /[\u0000-\u001f\u007f-\u009f\u2028\u2029\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]/u;

// JSON Schema's maxLength counts characters (code points), not UTF-16 units
const length = (text: string) => [...text].length;

/** The settings of the form's texts, or why not: the checks the server makes, in words. */
export function checkPlatform(input: PlatformInput): { settings?: LtiPlatformSettings; errors: PlatformErrors } {
    const errors: PlatformErrors = {};
    const value = Object.fromEntries(FIELDS.map((f) => [f, input[f].trim()])) as PlatformInput;
    for (const field of FIELDS) {
        const label = FIELD_TEXT[field].label.replace(/^\w/, (c) => c.toLowerCase());
        const text = value[field];
        if (field === 'deployment_ids') continue;
        if (text === '') {
            errors[field] = field === 'name' ? 'Give the platform a name.' : `The ${label} is missing.`;
        } else if (URL_FIELDS.has(field) && !/^https:\/\/\S+$/.test(text)) {
            errors[field] = `The ${label} must be an https:// address${/\s/.test(text) ? ' without spaces' : ''}.`;
        } else if ((field === 'name' || field === 'client_id') && HIDDEN_CHARACTERS.test(text)) {
            errors[field] = `The ${label} must not contain control characters.`;
        } else {
            const max = field === 'name' ? MAX_NAME : URL_FIELDS.has(field) ? MAX_URL : MAX_ID;
            if (length(text) > max) errors[field] = `The ${label} must be at most ${max} characters long.`;
        }
    }
    const ids = deploymentIds(input.deployment_ids);
    const twice = ids.find((id, i) => ids.indexOf(id) !== i);
    const long = ids.find((id) => length(id) > MAX_ID);
    if (ids.length === 0) errors.deployment_ids = 'List at least one deployment id.';
    else if (ids.length > MAX_DEPLOYMENTS) errors.deployment_ids = `At most ${MAX_DEPLOYMENTS} deployment ids (not ${ids.length}).`;
    else if (long !== undefined) errors.deployment_ids = `A deployment id must be at most ${MAX_ID} characters long.`;
    else if (twice !== undefined) errors.deployment_ids = `The deployment id "${twice}" is listed twice.`;
    if (Object.keys(errors).length > 0) return { errors };
    return {
        errors,
        settings: {
            name: value.name, issuer: value.issuer, client_id: value.client_id, auth_url: value.auth_url,
            token_url: value.token_url, jwks_url: value.jwks_url, deployment_ids: ids as [string, ...string[]],
        },
    };
}

interface ToolAddress { label: string; value: string; note: string }

/** The tool's addresses as Moodle's "Configure a tool manually" names them (Canvas's names in the note). */
export function toolAddresses(tool: LtiToolSettings): ToolAddress[] {
    const redirects = [...new Set([tool.launch_url, tool.deep_link_url].filter((url) => url !== ''))];
    return [
        { label: 'Tool URL', value: tool.launch_url, note: 'Canvas: Target Link URI' },
        { label: 'Initiate login URL', value: tool.login_url, note: 'Canvas: OpenID Connect Initiation Url' },
        { label: 'Redirection URI(s)', value: redirects.join('\n'), note: 'one a line; Canvas: Redirect URIs' },
        { label: 'Public keyset URL', value: tool.jwks_url, note: 'Moodle: Public key type "Keyset URL"; Canvas: Public JWK URL' },
        { label: 'Content Selection URL', value: tool.deep_link_url, note: 'deep linking; Canvas: the Deep Linking placement\'s Target Link URI' },
    ];
}

function copyText(label: string, value: string): void {
    const clipboard = navigator.clipboard;
    if (!clipboard) {
        toast(`${label}: the browser does not allow copying here; select the address instead.`, 'error');
        return;
    }
    clipboard.writeText(value).then(() => toast(`${label} copied`),
        () => toast(`${label}: the browser did not allow copying; select the address instead.`, 'error'));
}

function toolSection(tool: LtiToolSettings): HTMLElement {
    const rows = toolAddresses(tool).map((a) => h('tr', {},
        h('th', { scope: 'row' }, a.label, h('div', { class: 'muted lti-note' }, a.note)),
        h('td', {}, a.value ? h('code', { class: 'lti-address' }, a.value) : h('span', { class: 'muted' }, '(none while launches are off)')),
        h('td', {}, h('button', {
            type: 'button', class: 'small', 'aria-label': `Copy ${a.label}`, disabled: a.value === '',
            onclick: () => copyText(a.label, a.value),
        }, 'Copy'))));
    return h('section', { class: 'lab-section', 'data-testid': 'lti-tool', 'aria-labelledby': 'lti-tool-heading' },
        h('h2', { id: 'lti-tool-heading' }, 'Register tlmhub at the platform'),
        tool.enabled ? null : h('p', { class: 'notice', 'data-testid': 'lti-off' },
            'Launches are off: the server takes launches once it is started with --lti-key-file and --public-url ',
            '(see docs/sign-in.md). Platforms can be registered meanwhile.'),
        h('p', { class: 'muted' }, 'In Moodle: Site administration → Plugins → Activity modules → External tool → Manage tools → ',
            'configure a tool manually, LTI version "LTI 1.3", with these addresses:'),
        h('table', { class: 'model-table lti-tool-table' }, h('tbody', {}, ...rows)));
}

function deploymentsText(ids: string[]): string {
    return ids.length <= 3 ? ids.join(', ') : `${ids.slice(0, 3).join(', ')} and ${ids.length - 3} more`;
}

let formCount = 0;

export function renderLtiPlatforms(root: HTMLElement, session: Session): void {
    const main = h('main', { class: 'model-list-page lti-page' }, h('h1', {}, 'Learning platforms (LTI)'));
    root.replaceChildren(main);
    if (session.user?.role !== 'admin') {
        main.append(h('p', {}, 'Only administrators manage learning platforms.'));
        return;
    }
    const rest = session.rest;
    const pageMessage = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'lti-page-error' });
    const toolBox = h('div');
    const tableBody = h('tbody');
    const empty = h('p', { class: 'muted', hidden: true }, 'No platform is registered yet.');

    // ---- the form
    const id = `lti-form-${++formCount}`;
    let editing: LtiPlatform | null = null;
    const inputs = {} as Record<PlatformField, HTMLInputElement | HTMLTextAreaElement>;
    const fieldErrors = {} as Record<PlatformField, HTMLElement>;
    const fields = FIELDS.map((field) => {
        const text = FIELD_TEXT[field];
        const inputId = `${id}-${field}`;
        const input = field === 'deployment_ids'
            ? h('textarea', { id: inputId, name: field, rows: 2, placeholder: 'e.g. 1' })
            : h('input', { id: inputId, name: field, type: URL_FIELDS.has(field) ? 'url' : 'text', placeholder: text.placeholder ? `e.g. ${text.placeholder}` : '',
                autocomplete: 'off', spellcheck: false });
        input.setAttribute('aria-describedby', `${inputId}-hint ${inputId}-error`);
        inputs[field] = input;
        fieldErrors[field] = h('span', { class: 'field-error', id: `${inputId}-error`, hidden: true });
        return h('div', { class: 'lti-field' }, h('label', { for: inputId }, text.label), input,
            h('span', { class: 'muted lti-note', id: `${inputId}-hint` }, text.hint), fieldErrors[field]);
    });
    const showError = (field: PlatformField, message: string, marked = message !== '') => {
        fieldErrors[field].textContent = message;
        fieldErrors[field].hidden = message === '';
        inputs[field].classList.toggle('invalid', marked);
        inputs[field].setAttribute('aria-invalid', String(marked));
    };
    const formHeading = h('h2', { id: `${id}-heading` });
    const submit = h('button', { type: 'submit', class: 'primary', 'data-testid': 'lti-save' });
    const cancel = h('button', { type: 'button', onclick: () => reset() }, 'Cancel');
    const formMessage = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'lti-form-error' });
    const form = h('form', {
        class: 'lti-form', 'aria-labelledby': formHeading.id, novalidate: true,
        onsubmit: (e: Event) => { e.preventDefault(); void save(); },
    }, formHeading, ...fields, formMessage, h('div', { class: 'toolbar' }, submit, cancel));

    const reset = (platform: LtiPlatform | null = null) => {
        editing = platform;
        formHeading.textContent = platform ? `Edit "${platform.name}"` : 'Register a platform';
        submit.textContent = platform ? 'Save changes' : 'Register platform';
        cancel.hidden = !platform;
        for (const field of FIELDS) {
            inputs[field].value = !platform ? '' : field === 'deployment_ids' ? platform.deployment_ids.join('\n') : platform[field];
            showError(field, '');
        }
        formMessage.textContent = '';
    };

    async function save(): Promise<void> {
        formMessage.textContent = '';
        const input = Object.fromEntries(FIELDS.map((f) => [f, inputs[f].value])) as PlatformInput;
        const { settings, errors } = checkPlatform(input);
        for (const field of FIELDS) showError(field, errors[field] ?? '');
        if (!settings) {
            formMessage.textContent = 'Some fields need a change: see the messages under them.';
            inputs[FIELDS.find((f) => errors[f])!].focus();
            return;
        }
        const changed = editing;
        submit.disabled = true;
        try {
            const saved = changed ? await rest.updateLtiPlatform(changed.id, settings) : await rest.createLtiPlatform(settings);
            toast(changed ? `Saved ${saved.name}` : `Registered ${saved.name}`);
            reset();
            await refresh();
        } catch (err) {
            formMessage.textContent = errorText(err);
            // the fields the refusal is about, marked (the message says why)
            if (err instanceof ApiError && err.code === 'conflict') {
                showError('issuer', '', true);
                showError('client_id', '', true);
            } else if (err instanceof ApiError) {
                const named = FIELDS.find((f) => new RegExp(`\\b${f}\\b`).test(err.message));
                if (named) showError(named, '', true);
            }
        } finally {
            submit.disabled = false;
        }
    }

    // ---- the registered platforms
    const row = (p: LtiPlatform) => h('tr', { 'data-platform': String(p.id) },
        h('td', {}, p.name),
        h('td', { class: 'lti-address' }, p.issuer),
        h('td', {}, p.client_id),
        h('td', { title: p.deployment_ids.join(', ') }, deploymentsText(p.deployment_ids)),
        h('td', {}, formatTime(p.created_at)),
        h('td', {}, h('div', { class: 'actions' },
            h('button', {
                type: 'button', 'aria-label': `Edit ${p.name}`,
                onclick: () => {
                    reset(p);
                    form.scrollIntoView?.({ block: 'nearest' });
                    inputs.name.focus();
                },
            }, 'Edit'),
            h('button', { type: 'button', class: 'danger', 'aria-label': `Remove ${p.name}`, onclick: () => void remove(p) }, 'Remove'))));

    async function remove(p: LtiPlatform): Promise<void> {
        if (!confirm(`Remove "${p.name}"? Its course links, line items and pending scores go with it; the classes stay.`)) return;
        pageMessage.textContent = '';
        try {
            await rest.deleteLtiPlatform(p.id);
            toast(`Removed ${p.name}`);
            if (editing?.id === p.id) reset();
        } catch (err) {
            pageMessage.textContent = `${p.name}: ${errorText(err)}`;
        }
        await refresh();
    }

    async function refresh(): Promise<void> {
        try {
            const list = await rest.ltiPlatforms();
            toolBox.replaceChildren(toolSection(list.tool));
            const platforms = [...list.platforms].sort((a, b) => a.name.localeCompare(b.name) || a.id - b.id);
            tableBody.replaceChildren(...platforms.map(row));
            empty.hidden = platforms.length > 0;
        } catch (err) {
            pageMessage.textContent = errorText(err);
        }
    }

    reset();
    main.append(
        h('p', { class: 'muted' }, 'Moodle, Canvas and other LTI 1.3 platforms that open tlmhub from their courses. ',
            'Register tlmhub at the platform with the addresses below, then the platform here with the values it shows.'),
        pageMessage,
        toolBox,
        h('section', { class: 'lab-section', 'data-testid': 'lti-platforms', 'aria-labelledby': `${id}-list` },
            h('h2', { id: `${id}-list` }, 'Registered platforms'),
            h('table', { class: 'model-table' },
                h('thead', {}, h('tr', {}, h('th', {}, 'Name'), h('th', {}, 'Issuer'), h('th', {}, 'Client id'),
                    h('th', {}, 'Deployments'), h('th', {}, 'Created'), h('th', {}, h('span', { class: 'visually-hidden' }, 'Actions')))),
                tableBody),
            empty),
        h('section', { class: 'lab-section' }, form));
    void refresh();
}
