// The user's display unit per quantity ("Pressure": "bar"), kept on the server
// (GET/PUT /api/v1/preferences) so that every browser of the user shows the same units.
import type { Preferences } from '../api/RestClient';
import { findDisplayUnit, type DisplayUnit } from './displayUnits';

export interface PreferencesStore {
    preferences(): Promise<Preferences>;
    setPreferences(preferences: Preferences): Promise<Preferences>;
}

export class UnitPreferences {
    private units = new Map<string, string>();
    private loading: Promise<void> | null = null;
    private readonly listeners = new Set<() => void>();

    /** `onSaveError` tells the user a choice was not stored (it still holds until the page is left). */
    constructor(private readonly store: PreferencesStore, private readonly onSaveError: (e: unknown) => void) {}

    /**
     * Loads the stored choices once (again after forget()). A failure leaves the base units:
     * plots must work without the preferences.
     */
    load(): Promise<void> {
        if (this.loading) return this.loading;
        const loading = this.store.preferences().then((stored) => {
            // the user logged out meanwhile: not theirs any more
            if (this.loading !== loading) return;
            // a choice made while loading wins over the stored one
            const chosen = this.units;
            this.units = new Map(Object.entries(stored.units ?? {}));
            for (const [quantity, unit] of chosen) this.units.set(quantity, unit);
            this.notify();
        }, () => undefined);
        this.loading = loading;
        return loading;
    }

    /** Another user logs in: their choices are loaded anew. */
    forget(): void {
        this.units.clear();
        this.loading = null;
        this.notify();
    }

    /** The chosen unit of a quantity; null for the base unit with SI prefixes (no choice, or one this app does not know). */
    unitOf(quantity: string | null): DisplayUnit | null {
        if (quantity === null) return null;
        const name = this.units.get(quantity);
        return name === undefined ? null : findDisplayUnit(quantity, name);
    }

    /** Shows `quantity` in `unit` (null: back to SI prefixes) everywhere and stores the choice. */
    async choose(quantity: string, unit: string | null): Promise<void> {
        if (unit === null) this.units.delete(quantity);
        else this.units.set(quantity, unit);
        this.notify();
        try {
            await this.store.setPreferences({ units: Object.fromEntries(this.units) });
        } catch (e) {
            this.onSaveError(e);
        }
    }

    /** Calls `listener` when a choice changes; returns the unsubscribe. */
    subscribe(listener: () => void): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    private notify(): void {
        for (const listener of this.listeners) listener();
    }
}
