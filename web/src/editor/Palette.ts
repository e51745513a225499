// Component palette from the catalogue, grouped by domain and searchable. Drag an entry onto
// the canvas, or double-click it to place it in the middle of the view.
import { h } from '../ui/dom';
import { domainOf } from './icons';
import type { CatalogueEntry } from '../protocol/types';

const DOMAIN_ORDER = ['Hydraulic', 'Mechanic', 'Signal', 'Electric', 'Pneumatic', 'Aero', 'Other', 'Subsystem'];

export function groupByDomain(entries: CatalogueEntry[]): Map<string, CatalogueEntry[]> {
    const groups = new Map<string, CatalogueEntry[]>();
    for (const d of DOMAIN_ORDER) groups.set(d, []);
    for (const e of entries) {
        const domain = groups.has(e.domain) ? e.domain : 'Other';
        groups.get(domain)!.push(e);
    }
    for (const list of groups.values()) list.sort((a, b) => a.type.localeCompare(b.type));
    for (const [d, list] of groups) if (list.length === 0) groups.delete(d);
    return groups;
}

/** Entries whose type contains every word of the query (case-insensitive). */
export function filterCatalogue(entries: CatalogueEntry[], query: string): CatalogueEntry[] {
    const words = query.toLowerCase().split(/\s+/).filter(Boolean);
    if (words.length === 0) return entries;
    return entries.filter((e) => {
        const text = `${e.type} ${e.domain}`.toLowerCase();
        return words.every((w) => text.includes(w));
    });
}

export function createPalette(catalogue: CatalogueEntry[], place: (type: string) => void): HTMLElement {
    // subsystems are not in the catalogue but can be added
    const entries: CatalogueEntry[] = [...catalogue, { type: 'Subsystem', kind: 'S', domain: 'Subsystem', ports: [], parameters: [] }];
    const search = h('input', { type: 'search', placeholder: 'Search components', class: 'palette-search', 'aria-label': 'Search components' });
    const groupsBox = h('div', { class: 'palette-groups' });
    const collapsed = new Set<string>(DOMAIN_ORDER.filter((d) => d !== 'Hydraulic'));

    const item = (e: CatalogueEntry) => h('li', {
        class: 'palette-item', draggable: 'true', 'data-type': e.type, title: `${e.type} (${e.kind}) — drag to the canvas or double-click`,
        ondragstart: (ev: DragEvent) => {
            ev.dataTransfer?.setData('application/x-tlmhub-type', e.type);
            ev.dataTransfer?.setData('text/plain', e.type);
            if (ev.dataTransfer) ev.dataTransfer.effectAllowed = 'copy';
        },
        ondblclick: () => place(e.type),
    }, h('span', { class: `swatch swatch-${domainOf(e.type).toLowerCase()}` }), e.type.replace(/^(Hydraulic|Mechanic|Signal|Electric|Pneumatic|Aero)/, '') || e.type);

    const draw = () => {
        const query = search.value.trim();
        const groups = groupByDomain(filterCatalogue(entries, query));
        groupsBox.replaceChildren(...[...groups].map(([domain, list]) => {
            const open = query !== '' || !collapsed.has(domain);
            return h('section', { class: 'palette-group', 'data-domain': domain },
                h('button', {
                    class: 'palette-domain', 'aria-expanded': String(open),
                    onclick: () => { if (collapsed.has(domain)) collapsed.delete(domain); else collapsed.add(domain); draw(); },
                }, `${open ? '▾' : '▸'} ${domain} (${list.length})`),
                open ? h('ul', {}, ...list.map(item)) : null);
        }));
    };
    search.addEventListener('input', draw);
    draw();
    return h('aside', { class: 'palette', 'aria-label': 'Component palette' }, search, groupsBox);
}
