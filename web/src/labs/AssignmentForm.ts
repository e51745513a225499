// The form of an assignment, to create one or change it: title, instructions (Markdown, with
// a preview), the template and solution models from the teacher's models, opening and due
// times, and what students may change (everything, or listed parameters within bounds).
// Changing an assignment, the teacher sees first what the server warned of (AssignmentWarnings).
import { errorText, h } from '../ui/dom';
import type { Model, ModelSummary, System } from '../protocol/types';
import type { AllowedParameter, AssignmentInput, EditMode } from './types';
import { fromDatetimeLocal, optionalNumber, toDatetimeLocal } from './format';
import { markdownBlock } from './markdown';
import { assignmentWarnings, type TeacherAssignment } from './AssignmentWarnings';

export interface AssignmentFormOptions {
    models: ModelSummary[];
    /** the assignment changed; absent: a new one */
    initial?: TeacherAssignment;
    submitLabel: string;
    onSubmit: (input: AssignmentInput) => Promise<void>;
    onCancel: () => void;
    /** the model, for the names of its parameters */
    loadModel?: (id: number) => Promise<Model>;
}

let formCount = 0;

/** `Comp.param` names of a model's parameters (subsystems as `Sub$Comp.param`) and its system parameters. */
export function parameterNames(system: System, prefix = ''): string[] {
    const names: string[] = prefix === '' ? system.parameters.map((p) => p.name) : [];
    for (const c of system.components) {
        if (c.system) names.push(...parameterNames(c.system, `${prefix}${c.name}$`));
        for (const p of c.parameters) {
            // start values of nodes (P1#HeatFlow) are no parameters a student tunes
            if (p.name.includes('#') && !p.name.endsWith('#Value')) continue;
            names.push(`${prefix}${c.name}.${p.name.replace(/#Value$/, '')}`);
        }
    }
    return names;
}

export function assignmentForm(options: AssignmentFormOptions): HTMLElement {
    const { models, initial } = options;
    const id = `assignment-form-${++formCount}`;
    const title = h('input', { name: 'title', required: true, value: initial?.title ?? '' });
    const instructions = h('textarea', { name: 'instructions', rows: 8, placeholder: '# Task\nSet **GainP.k** so that …' });
    instructions.value = initial?.instructions ?? '';
    const preview = h('div', { class: 'markdown-preview' });
    const showPreview = () => preview.replaceChildren(instructions.value.trim()
        ? markdownBlock(instructions.value) : h('p', { class: 'muted' }, 'The preview of the instructions shows here.'));
    instructions.addEventListener('input', showPreview);
    showPreview();

    const modelOptions = (noneLabel: string) => [
        h('option', { value: '' }, noneLabel),
        ...[...models].sort((a, b) => Number(a.is_example) - Number(b.is_example) || a.name.localeCompare(b.name))
            .map((m) => h('option', { value: String(m.id) }, m.is_example ? `${m.name} (example)` : m.name)),
    ];
    const template = h('select', { name: 'template', required: !initial },
        ...modelOptions(initial ? '(keep the current template)' : '(choose a model)'));
    const solution = h('select', { name: 'solution' }, ...modelOptions(initial ? '(keep the current solution)' : '(none yet)'));

    const opens = h('input', { type: 'datetime-local', name: 'opens', value: toDatetimeLocal(initial?.opens_at) });
    const due = h('input', { type: 'datetime-local', name: 'due', value: toDatetimeLocal(initial?.due_at) });
    const editMode = h('select', { name: 'edit-mode' },
        h('option', { value: 'parameters', selected: (initial?.edit_mode ?? 'parameters') === 'parameters' }, 'only the listed parameters'),
        h('option', { value: 'free', selected: initial?.edit_mode === 'free' }, 'anything (free)'));

    // ---- allowed parameters
    const suggestions = h('datalist', { id: `${id}-names` });
    const rows = h('tbody');
    const addRow = (p?: AllowedParameter) => {
        const n = rows.children.length + 1;
        const name = h('input', { 'aria-label': `Parameter ${n} name`, list: suggestions.id, value: p?.name ?? '', placeholder: 'GainP.k', class: 'param-name-input' });
        const min = h('input', { 'aria-label': `Parameter ${n} min`, inputmode: 'decimal', value: p?.min ?? '', class: 'num' });
        const max = h('input', { 'aria-label': `Parameter ${n} max`, inputmode: 'decimal', value: p?.max ?? '', class: 'num' });
        const row = h('tr', { class: 'allowed-parameter' }, h('td', {}, name), h('td', {}, min), h('td', {}, max),
            h('td', {}, h('button', { type: 'button', class: 'small danger', title: 'Remove', onclick: () => row.remove() }, '✕')));
        rows.append(row);
    };
    for (const p of initial?.parameters ?? []) addRow(p);
    const parameterBox = h('fieldset', { class: 'allowed-parameters' },
        h('legend', {}, 'Parameters students may change'),
        h('table', { class: 'plain-table' }, h('thead', {}, h('tr', {}, h('th', {}, 'Name'), h('th', {}, 'Min'), h('th', {}, 'Max'), h('th', {}))), rows),
        h('button', { type: 'button', onclick: () => addRow() }, 'Add parameter'), suggestions);
    const showParameters = () => { parameterBox.hidden = editMode.value !== 'parameters'; };
    editMode.addEventListener('change', showParameters);
    showParameters();
    template.addEventListener('change', async () => {
        const modelId = Number(template.value);
        if (!modelId || !options.loadModel) return;
        try {
            const model = await options.loadModel(modelId);
            suggestions.replaceChildren(...parameterNames(model.system).map((n) => h('option', { value: n })));
        } catch {
            // suggestions only
        }
    });

    const message = h('p', { class: 'form-error', role: 'alert' });
    const submit = h('button', { type: 'submit', class: 'primary' }, options.submitLabel);
    const readInput = (): AssignmentInput => {
        const input: AssignmentInput = {
            title: title.value.trim(),
            instructions: instructions.value,
            edit_mode: editMode.value as EditMode,
        };
        if (template.value) input.template_model_id = Number(template.value);
        if (solution.value) input.solution_model_id = Number(solution.value);
        // a time the form shows unchanged is not sent (the field holds whole minutes only)
        const opensAt = fromDatetimeLocal(opens.value);
        if (opensAt !== undefined && opens.value !== toDatetimeLocal(initial?.opens_at)) input.opens_at = opensAt;
        const dueAt = fromDatetimeLocal(due.value);
        if (dueAt === undefined) {
            if (initial?.due_at) input.due_at = 0;   // cleared: no deadline
        } else if (due.value !== toDatetimeLocal(initial?.due_at)) {
            input.due_at = dueAt;
        }
        const parameters: AllowedParameter[] = [];
        if (input.edit_mode === 'parameters') {
            for (const row of rows.querySelectorAll('tr')) {
                const [name, min, max] = [...row.querySelectorAll('input')].map((i) => i.value);
                if (!name.trim()) continue;
                const p: AllowedParameter = { name: name.trim() };
                const lo = optionalNumber(min);
                const hi = optionalNumber(max);
                if (Number.isNaN(lo) || Number.isNaN(hi)) throw new Error(`${p.name}: min and max must be numbers`);
                if (lo !== undefined) p.min = lo;
                if (hi !== undefined) p.max = hi;
                if (lo !== undefined && hi !== undefined && lo > hi) throw new Error(`${p.name}: min is above max`);
                parameters.push(p);
            }
        }
        input.parameters = parameters;
        return input;
    };

    return h('form', {
        class: 'assignment-form', 'aria-label': initial ? 'Edit assignment' : 'New assignment',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            message.textContent = '';
            submit.disabled = true;
            try {
                const input = readInput();
                if (!initial && !input.template_model_id) throw new Error('Choose the template model the students get.');
                await options.onSubmit(input);
            } catch (err) {
                message.textContent = errorText(err);
            } finally {
                submit.disabled = false;
            }
        },
    },
    initial ? assignmentWarnings(initial) : null,
    h('label', {}, 'Title', title),
    h('div', { class: 'instructions-editor' },
        h('label', {}, 'Instructions (Markdown)', instructions),
        h('div', { class: 'preview-box' }, h('span', { class: 'muted' }, 'Preview'), preview)),
    h('div', { class: 'form-row' },
        h('label', {}, 'Template model', template),
        h('label', {}, 'Solution model', solution)),
    h('div', { class: 'form-row' },
        h('label', {}, 'Opens', opens),
        h('label', {}, 'Due (empty: no deadline)', due),
        h('label', {}, 'Students may change', editMode)),
    parameterBox,
    h('div', { class: 'toolbar' }, submit, h('button', { type: 'button', onclick: options.onCancel }, 'Cancel')),
    message);
}
