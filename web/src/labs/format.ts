// How lab pages write times, numbers and datetime inputs.

/** A unix time in the browser's time zone; "—" for none. */
export function formatTime(unix: number | null | undefined): string {
    if (!unix) return '—';
    return new Date(unix * 1000).toLocaleString(undefined, { dateStyle: 'medium', timeStyle: 'short' });
}

/** A number without noise digits (4 significant), "—" for none. */
export function formatNumber(value: number | null | undefined, digits = 4): string {
    if (value === null || value === undefined || !Number.isFinite(value)) return '—';
    if (value !== 0 && (Math.abs(value) >= 1e6 || Math.abs(value) < 1e-3)) return value.toExponential(digits - 1);
    return String(Number(value.toPrecision(digits)));
}

export function formatScore(score: number | null | undefined, max: number | null | undefined): string {
    if (score === null || score === undefined) return '—';
    return `${formatNumber(score)} / ${formatNumber(max)}`;
}

/** The value of a datetime-local input for a unix time (local time, minutes). */
export function toDatetimeLocal(unix: number | null | undefined): string {
    if (!unix) return '';
    const d = new Date(unix * 1000);
    const pad = (n: number) => String(n).padStart(2, '0');
    return `${d.getFullYear()}-${pad(d.getMonth() + 1)}-${pad(d.getDate())}T${pad(d.getHours())}:${pad(d.getMinutes())}`;
}

/** A datetime-local input's value as unix seconds; undefined when empty or not a time. */
export function fromDatetimeLocal(value: string): number | undefined {
    if (!value) return undefined;
    const ms = new Date(value).getTime();
    return Number.isFinite(ms) ? Math.round(ms / 1000) : undefined;
}

/** A number field: undefined when empty, NaN when not a number. */
export function optionalNumber(text: string): number | undefined {
    const t = text.trim();
    return t === '' ? undefined : Number(t);
}
