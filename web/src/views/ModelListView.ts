// The model list: the user's own models and the examples, searched by name or owner and
// sorted by a column header; create, rename, duplicate, delete, upload a .hmf and download as .hmf.
import { downloadText, errorText, h, toast } from '../ui/dom';
import { filterRows, sortableTable, type Column, type SortOrder } from '../ui/sortableTable';
import type { Session } from '../app/Session';
import type { ModelSummary } from '../protocol/types';

export async function renderModelList(root: HTMLElement, session: Session, open: (id: number) => void): Promise<void> {
    const rest = session.rest;
    const list = h('div', { class: 'model-tables' }, h('p', { class: 'muted' }, 'Loading…'));
    const search = h('input', {
        type: 'search', name: 'model-search', placeholder: 'Search models by name or owner', 'aria-label': 'Search models',
        oninput: () => showModels(),
    });
    let models: ModelSummary[] = [];
    const showModels = () => list.replaceChildren(...tables(filterRows(models, search.value, (m) => `${m.name} ${m.owner.username}`)));
    const refresh = async () => {
        try {
            models = await rest.listModels();
            showModels();
        } catch (e) {
            list.replaceChildren(h('p', { class: 'form-error' }, errorText(e)));
        }
    };
    const act = async (work: () => Promise<unknown>, done?: string) => {
        try {
            await work();
            if (done) toast(done);
            await refresh();
        } catch (e) {
            toast(errorText(e), 'error');
        }
    };
    const mine = (m: ModelSummary) => session.user?.role === 'admin' || m.owner.id === session.user?.id;

    const actions = (m: ModelSummary) => h('div', { class: 'actions' },
            h('button', { onclick: () => open(m.id) }, 'Open'),
            mine(m) && (!m.is_example || session.user?.role === 'admin') ? h('button', {
                onclick: () => {
                    const name = prompt('New name', m.name);
                    if (name && name !== m.name) void act(() => rest.renameModel(m.id, name), 'Renamed');
                },
            }, 'Rename') : null,
            h('button', {
                onclick: () => {
                    const name = prompt('Name of the copy', `${m.name} copy`);
                    if (name) void act(() => rest.duplicateModel(m.id, name), 'Duplicated');
                },
            }, 'Duplicate'),
            h('button', {
                onclick: () => void act(async () => downloadText(`${m.name}.hmf`, await rest.downloadHmf(m.id), 'application/xml')),
            }, 'Download .hmf'),
            mine(m) && (!m.is_example || session.user?.role === 'admin') ? h('button', {
                class: 'danger',
                onclick: () => {
                    if (confirm(`Delete model "${m.name}"?`)) void act(() => rest.deleteModel(m.id), 'Deleted');
                },
            }, 'Delete') : null);

    const columns: Column<ModelSummary>[] = [
        { key: 'name', label: 'Name', value: (m) => m.name, cell: (m) => h('a', { href: `#/model/${m.id}`, class: 'model-link' }, m.name) },
        { key: 'owner', label: 'Owner', value: (m) => m.owner.username },
        { key: 'changed', label: 'Changed', value: (m) => m.updated_at, largestFirst: true, cell: (m) => new Date(m.updated_at * 1000).toLocaleString() },
        { key: 'actions', label: '', value: () => null, cell: actions, sortable: false },
    ];
    // each table keeps the order its headers were clicked to while the list is searched or changed
    const orders = new Map<string, SortOrder>();
    const table = (title: string, shown: ModelSummary[], testId: string) => h('section', { class: 'model-section', dataset: { testid: testId } },
        h('h2', {}, title),
        shown.length === 0 ? h('p', { class: 'muted' }, search.value.trim() ? 'No model matches the search.' : 'None yet.') : sortableTable({
            columns, rows: shown, order: orders.get(testId) ?? { key: 'name', direction: 'ascending' },
            onOrder: (order) => orders.set(testId, order),
            rowAttrs: (m) => ({ dataset: { modelId: String(m.id) } }),
        }).element);

    const tables = (shown: ModelSummary[]) => {
        const own = shown.filter((m) => !m.is_example && m.owner.id === session.user?.id);
        const others = shown.filter((m) => !m.is_example && m.owner.id !== session.user?.id);
        const examples = shown.filter((m) => m.is_example);
        return [
            table('My models', own, 'own-models'),
            others.length > 0 ? table('Models of others', others, 'other-models') : null,
            table('Examples', examples, 'example-models'),
        ].filter((x): x is HTMLElement => x !== null);
    };

    const newName = h('input', { name: 'new-model-name', placeholder: 'New model name' });
    const upload = h('input', {
        type: 'file', accept: '.hmf,.xml', name: 'upload-hmf',
        onchange: async () => {
            const file = upload.files?.[0];
            if (!file) return;
            const name = file.name.replace(/\.(hmf|xml)$/i, '');
            await act(async () => rest.uploadHmf(await file.text(), name), `Uploaded ${file.name}`);
            upload.value = '';
        },
    });
    const toolbar = h('form', {
        class: 'toolbar',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            const name = newName.value.trim();
            if (!name) return;
            try {
                const created = await rest.createModel(name);
                open(created.id);
            } catch (err) {
                toast(errorText(err), 'error');
            }
        },
    }, newName, h('button', { type: 'submit', class: 'primary' }, 'Create'),
    h('label', { class: 'upload' }, 'Upload .hmf ', upload));

    root.replaceChildren(h('main', { class: 'model-list-page' }, toolbar, h('div', { class: 'list-search' }, search), list));
    await refresh();
}
