// The palette's contents: component types grouped by Hopsan's library folders and found by
// display name, type name or folder.
import { displayNameOf, libraryOf } from '../model/appearance';
import type { CatalogueEntry } from '../protocol/types';

const FOLDER_ORDER = ['Hydraulic', 'Mechanic', 'Signal', 'Electric', 'Pneumatic', 'Connectivity', 'Subsystem', 'Special', 'Experimental', 'Other', 'Obsolete'];

export interface PaletteFolder {
    name: string;
    /** Entries by sub-folder ('' for those directly in the folder), each sorted by display name. */
    subfolders: Map<string, CatalogueEntry[]>;
    count: number;
}

export function groupByLibrary(entries: CatalogueEntry[]): PaletteFolder[] {
    const folders = new Map<string, PaletteFolder>();
    for (const e of entries) {
        const [top, ...rest] = libraryOf(e.type).split('/');
        const folder = folders.get(top) ?? { name: top, subfolders: new Map(), count: 0 };
        folders.set(top, folder);
        const sub = rest.join('/');
        folder.subfolders.set(sub, [...(folder.subfolders.get(sub) ?? []), e]);
        folder.count++;
    }
    const rank = (name: string) => (FOLDER_ORDER.includes(name) ? FOLDER_ORDER.indexOf(name) : FOLDER_ORDER.indexOf('Other') - 0.5);
    const sorted = [...folders.values()].sort((a, b) => rank(a.name) - rank(b.name) || a.name.localeCompare(b.name));
    for (const f of sorted) {
        f.subfolders = new Map([...f.subfolders].sort(([a], [b]) => a.localeCompare(b)));
        for (const list of f.subfolders.values()) list.sort((a, b) => displayNameOf(a.type).localeCompare(displayNameOf(b.type)));
    }
    return sorted;
}

/** Entries whose display name, type or folder contain every word of the query (case-insensitive). */
export function filterCatalogue(entries: CatalogueEntry[], query: string): CatalogueEntry[] {
    const words = query.toLowerCase().split(/\s+/).filter(Boolean);
    if (words.length === 0) return entries;
    return entries.filter((e) => {
        const text = `${displayNameOf(e.type)} ${e.type} ${libraryOf(e.type)}`.toLowerCase();
        return words.every((w) => text.includes(w));
    });
}
