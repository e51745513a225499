// Component palette from the catalogue, in Hopsan's library folders, with our icons and
// display names, searchable by display name or type. Drag an entry onto the canvas, or
// double-click it to place it in the middle of the view.
import { h, s } from '../ui/dom';
import { componentIcon, fittedHalfSize } from './icons';
import { filterCatalogue, groupByLibrary } from './paletteGroups';
import { displayNameOf } from '../model/appearance';
import type { CatalogueEntry } from '../protocol/types';

function paletteIcon(type: string): SVGSVGElement {
    // at the type's own aspect, as on the canvas (a pump square, a cylinder long)
    const [w, h] = fittedHalfSize(type, 10, 8);
    return s('svg', { class: 'palette-icon', width: 22, height: 18, viewBox: '-11 -9 22 18', 'aria-hidden': 'true' }, componentIcon(type, w, h));
}

export function createPalette(catalogue: CatalogueEntry[], place: (type: string) => void): HTMLElement {
    // subsystems are not in the catalogue but can be added
    const entries: CatalogueEntry[] = [...catalogue, { type: 'Subsystem', kind: 'S', domain: 'Subsystem', ports: [], parameters: [] }];
    const search = h('input', { type: 'search', placeholder: 'Search components', class: 'palette-search', 'aria-label': 'Search components' });
    const groupsBox = h('div', { class: 'palette-groups' });
    const expanded = new Set<string>(['Hydraulic']);

    const item = (e: CatalogueEntry) => h('li', {
        class: 'palette-item', draggable: 'true', 'data-type': e.type,
        title: `${displayNameOf(e.type)} — ${e.type} (${e.kind}); drag to the canvas or double-click`,
        ondragstart: (ev: DragEvent) => {
            ev.dataTransfer?.setData('application/x-tlmhub-type', e.type);
            ev.dataTransfer?.setData('text/plain', e.type);
            if (ev.dataTransfer) ev.dataTransfer.effectAllowed = 'copy';
        },
        ondblclick: () => place(e.type),
    }, paletteIcon(e.type), h('span', { class: 'palette-name' }, displayNameOf(e.type)));

    const draw = () => {
        const query = search.value.trim();
        groupsBox.replaceChildren(...groupByLibrary(filterCatalogue(entries, query)).map((folder) => {
            const open = query !== '' || expanded.has(folder.name);
            return h('section', { class: 'palette-group', 'data-folder': folder.name },
                h('button', {
                    class: 'palette-domain', 'aria-expanded': String(open),
                    onclick: () => { if (!expanded.delete(folder.name)) expanded.add(folder.name); draw(); },
                }, `${open ? '▾' : '▸'} ${folder.name} (${folder.count})`),
                open ? h('div', {}, ...[...folder.subfolders].map(([sub, list]) => h('div', { class: 'palette-subfolder' },
                    sub ? h('div', { class: 'palette-subfolder-name' }, sub.replaceAll('/', ' › ')) : null,
                    h('ul', {}, ...list.map(item))))) : null);
        }));
    };
    search.addEventListener('input', draw);
    draw();
    return h('aside', { class: 'palette', 'aria-label': 'Component palette' }, search, groupsBox);
}
