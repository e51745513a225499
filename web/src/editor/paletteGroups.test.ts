import { describe, expect, it } from 'vitest';
import { filterCatalogue, groupByLibrary } from './paletteGroups';
import type { CatalogueEntry } from '../protocol/types';

const entry = (type: string): CatalogueEntry => ({ type, kind: 'S', domain: 'Signal', ports: [], parameters: [] });
const entries = ['SignalSink', 'SignalGain', 'Hydraulic43Valve', 'HydraulicCylinderC', 'HydraulicTankC', 'Subsystem', 'MadeUpType'].map(entry);

describe('palette groups', () => {
    it('"scope" finds the scope (SignalSink) by its display name; types are found by type name', () => {
        expect(filterCatalogue(entries, 'scope').map((e) => e.type)).toEqual(['SignalSink']);
        expect(filterCatalogue(entries, 'SignalGain').map((e) => e.type)).toEqual(['SignalGain']);
        expect(filterCatalogue(entries, 'hydraulic valve').map((e) => e.type)).toEqual(['Hydraulic43Valve']);
    });

    it('groups by Hopsan library folder and sub-folder', () => {
        const folders = groupByLibrary(entries);
        expect(folders.map((f) => f.name)).toEqual(['Hydraulic', 'Signal', 'Subsystem', 'Other']);
        const hydraulic = folders[0];
        expect([...hydraulic.subfolders.keys()]).toEqual(['LinearActuators', 'Sources&Sinks', 'Valves/FlowControlValves']);
        expect(hydraulic.count).toBe(3);
        expect(folders[3].subfolders.get('')!.map((e) => e.type)).toEqual(['MadeUpType']);
    });
});
