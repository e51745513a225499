import { describe, expect, it } from 'vitest';
import { UnitPreferences } from './unitPreferences';
import type { Preferences } from '../api/RestClient';

/** A preferences store in memory that can be told to fail. */
function store(stored: Preferences = { units: {} }) {
    const saved: Preferences[] = [];
    let failing = false;
    return {
        saved,
        fail() { failing = true; },
        async preferences() {
            if (failing) throw new Error('no route');
            return stored;
        },
        async setPreferences(p: Preferences) {
            if (failing) throw new Error('refused');
            saved.push(p);
            return p;
        },
    };
}

describe('unit preferences', () => {
    it('apply the stored choices once loaded, ignoring units this app does not know', async () => {
        const prefs = new UnitPreferences(store({ units: { Pressure: 'bar', Flow: 'l/min', Position: 'furlong', Nonsense: 'x' } }), () => undefined);
        let changes = 0;
        prefs.subscribe(() => ++changes);
        expect(prefs.unitOf('Pressure')).toBeNull();
        await prefs.load();
        expect(changes).toBe(1);
        expect(prefs.unitOf('Pressure')).toEqual({ name: 'bar', scale: 1e5, offset: 0 });
        expect(prefs.unitOf('Flow')?.name).toBe('l/min');
        expect(prefs.unitOf('Position')).toBeNull();
        expect(prefs.unitOf('Nonsense')).toBeNull();
        expect(prefs.unitOf(null)).toBeNull();
    });

    it('a choice shows at once and is stored with the others; back to SI prefixes removes it', async () => {
        const server = store({ units: { Pressure: 'bar' } });
        const prefs = new UnitPreferences(server, () => undefined);
        await prefs.load();
        await prefs.choose('Temperature', 'C');
        expect(prefs.unitOf('Temperature')).toEqual({ name: 'C', scale: 1, offset: 273.15 });
        await prefs.choose('Pressure', null);
        expect(prefs.unitOf('Pressure')).toBeNull();
        expect(server.saved).toEqual([{ units: { Pressure: 'bar', Temperature: 'C' } }, { units: { Temperature: 'C' } }]);
    });

    it('without the server the base units stay; a choice not saved is reported and still shown', async () => {
        const server = store({ units: { Pressure: 'bar' } });
        server.fail();
        const errors: unknown[] = [];
        const prefs = new UnitPreferences(server, (e) => errors.push(e));
        await prefs.load();
        expect(prefs.unitOf('Pressure')).toBeNull();
        await prefs.choose('Flow', 'l/min');
        expect(errors).toHaveLength(1);
        expect(prefs.unitOf('Flow')?.name).toBe('l/min');
    });

    it('a choice made while loading wins; after forget() the next user\'s choices are loaded', async () => {
        const server = store({ units: { Pressure: 'MPa', Flow: 'l/min' } });
        const prefs = new UnitPreferences(server, () => undefined);
        const loading = prefs.load();
        await prefs.choose('Pressure', 'bar');
        await loading;
        expect(prefs.unitOf('Pressure')?.name).toBe('bar');
        expect(prefs.unitOf('Flow')?.name).toBe('l/min');
        prefs.forget();
        expect(prefs.unitOf('Flow')).toBeNull();
        await prefs.load();
        expect(prefs.unitOf('Flow')?.name).toBe('l/min');
    });
});
