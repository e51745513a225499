// Server messages in words a person reads. The server's request validation answers with the
// field's path (`body.password: must be at least 8 characters long`, `message.pose.x: expected
// number, got string`); the core names node types by their class (`NodeHydraulic`). Where such
// a message reaches the user it becomes a sentence: "The password must be at least 8
// characters long." A message that is already in words passes unchanged.

/** Field names as the forms label them; any other field reads as its words (`log_samples` → "log samples"). */
const FIELD_WORDS: Record<string, string> = {
    username: 'user name',
    password: 'password',
    new_password: 'new password',
    old_password: 'current password',
    role: 'role',
    opens_at: 'opening time',
    due_at: 'due time',
    edit_mode: 'edit mode',
    template_model_id: 'template model',
    solution_model_id: 'solution model',
    model_id: 'model',
    log_samples: 'number of logged samples',
    start: 'start time',
    stop: 'stop time',
    step: 'time step',
    min: 'minimum',
    max: 'maximum',
    hmf: 'model file',
    new_name: 'new name',
    component_type: 'component type',
    expires_in_days: 'lifetime in days',
    client_id: 'client id',
    auth_url: 'authentication URL',
    token_url: 'token URL',
    jwks_url: 'keyset URL',
    deployment_ids: 'deployment ids',
};

export function fieldWords(key: string): string {
    return FIELD_WORDS[key] ?? key.replace(/_/g, ' ');
}

const TYPE_WORDS: Record<string, string> = {
    number: 'a number', integer: 'a whole number', string: 'text', boolean: 'yes or no',
    array: 'a list', object: 'a group of fields', null: 'empty',
};

/** `NodeHydraulic` → "hydraulic". */
export function nodeTypeWords(type: string): string {
    return type.replace(/^Node/, '').replace(/([a-z])([A-Z])/g, '$1 $2').toLowerCase();
}

interface Path { field: string; where: string }

// body.parameters[2].min -> the field "min", where " (in parameter 3)"
function readPath(path: string): Path {
    const parts = [...path.matchAll(/\.([A-Za-z_]\w*)|\[(\d+)\]|\["([^"]*)"\]/g)];
    let field = '';
    let where = '';
    for (let i = 0; i < parts.length; ++i) {
        const [, name, index, quoted] = parts[i];
        if (index !== undefined) {
            const list = field.replace(/s$/, '');
            where = ` (in ${list || 'item'} ${Number(index) + 1})`;
            field = '';
        } else {
            field = name ?? quoted ?? '';
        }
    }
    return { field: field ? fieldWords(field) : '', where };
}

function sentence(text: string): string {
    const t = text.trim();
    const capital = t.charAt(0).toUpperCase() + t.slice(1);
    return /[.!?]$/.test(capital) ? capital : `${capital}.`;
}

function listWords(json: string): string {
    try {
        const values = JSON.parse(json) as unknown[];
        if (!Array.isArray(values)) return json;
        const texts = values.map((v) => String(v));
        return texts.length <= 1 ? texts.join('') : `${texts.slice(0, -1).join(', ')} or ${texts[texts.length - 1]}`;
    } catch {
        return json;
    }
}

/** The reason of a validation message about `the` field, as the rest of a sentence. */
function reasonWords(the: string, reason: string): string {
    let m: RegExpMatchArray | null;
    if ((m = /^must be at least (\d+) characters? long/.exec(reason))) {
        return m[1] === '1' ? `${the} must not be empty` : `${the} must be at least ${m[1]} characters long`;
    }
    if ((m = /^must be at most (\d+) characters? long/.exec(reason))) return `${the} must be at most ${m[1]} characters long`;
    if ((m = /^must be >= (\S+?),? got (\S+)/.exec(reason))) return `${the} must be at least ${m[1]} (not ${m[2]})`;
    if ((m = /^must be <= (\S+?),? got (\S+)/.exec(reason))) return `${the} must be at most ${m[1]} (not ${m[2]})`;
    if ((m = /^must be > (\S+?),? got (\S+)/.exec(reason))) return `${the} must be more than ${m[1]} (not ${m[2]})`;
    if ((m = /^must be < (\S+?),? got (\S+)/.exec(reason))) return `${the} must be less than ${m[1]} (not ${m[2]})`;
    if ((m = /^expected one of (\[.*\]), got (.*)$/.exec(reason))) return `${the} must be ${listWords(m[1])}, not ${m[2]}`;
    if ((m = /^expected (\w+)(?: or (\w+))?, got (\w+)/.exec(reason))) {
        const wanted = [m[1], m[2]].filter(Boolean).map((t) => TYPE_WORDS[t!] ?? t).join(' or ');
        return `${the} must be ${wanted}, not ${TYPE_WORDS[m[3]] ?? m[3]}`;
    }
    if ((m = /^missing required property "([^"]+)"/.exec(reason))) return `the ${fieldWords(m[1])} is missing`;
    if (/^unknown property/.test(reason)) return `${the} is not a field this form takes`;
    if (/^does not match the pattern/.test(reason)) {
        return the === 'the user name'
            ? 'the user name may only use letters, digits, dots, dashes and underscores (at most 64)'
            : `${the} is not in the expected form`;
    }
    if (/^matches (none|\d+) of the (allowed )?forms/.test(reason)) return `${the} is not valid`;
    if (/^expected at least (\d+) items/.test(reason)) return `${the} needs at least ${/(\d+)/.exec(reason)![1]} entries`;
    if (/^expected at most (\d+) items/.test(reason)) return `${the} takes at most ${/(\d+)/.exec(reason)![1]} entries`;
    // a reason of the server's own: its field names in words
    const rest = reason.replace(/\b([a-z]+(?:_[a-z]+)+)\b/g, (k) => `the ${fieldWords(k)}`);
    return the ? `${the} ${rest}` : rest;
}

/** A validation message (`body.x: …`, `message.x: …`) as a sentence; null when `message` is not one. */
function validationWords(message: string): string | null {
    const m = /^(?:body|message)((?:\.[A-Za-z_]\w*|\[\d+\]|\["[^"]*"\])*)\s*:\s*(.+)$/s.exec(message.trim());
    if (!m) return null;
    const { field, where } = readPath(m[1]);
    const the = field ? `the ${field}` : '';
    const words = reasonWords(the || 'the request', m[2]);
    return sentence(`${words}${where}`);
}

const article = (word: string) => (/^[aeiou]/.test(word) ? 'an' : 'a');

/** The core's connection refusals with node types in words. */
function connectionWords(message: string): string | null {
    const m = /node types differ \((\w+) vs (\w+)\)/.exec(message);
    if (!m) return null;
    const [a, b] = [nodeTypeWords(m[1]), nodeTypeWords(m[2])];
    return sentence(message.replace(m[0], `${article(a)} ${a} port cannot be joined to ${article(b)} ${b} port (the node types differ)`));
}

/** `message` in words where it is a known machine form; else unchanged. */
export function inWords(message: string): string {
    return validationWords(message) ?? connectionWords(message) ?? message;
}
