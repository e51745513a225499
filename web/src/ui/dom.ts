// Tiny DOM helpers: build elements from a tag, attributes and children.
import { inWords } from './errorWords';

type Child = Node | string | number | null | undefined | false;
type Attrs = Record<string, unknown>;

function apply(el: Element, attrs: Attrs): void {
    for (const [key, value] of Object.entries(attrs)) {
        if (value === undefined || value === null || value === false) continue;
        if (key.startsWith('on') && typeof value === 'function') {
            el.addEventListener(key.slice(2).toLowerCase(), value as EventListener);
        } else if (key === 'class') {
            el.setAttribute('class', String(value));
        } else if (key === 'dataset' && typeof value === 'object') {
            for (const [k, v] of Object.entries(value as Record<string, string>)) (el as HTMLElement).dataset[k] = v;
        } else if (key in el && !(el instanceof SVGElement) && typeof value !== 'string') {
            (el as unknown as Record<string, unknown>)[key] = value;
        } else if (key === 'value' && el instanceof HTMLInputElement) {
            el.value = String(value);
        } else {
            el.setAttribute(key, value === true ? '' : String(value));
        }
    }
}

function append(el: Element, children: Child[]): void {
    for (const c of children) {
        if (c === null || c === undefined || c === false) continue;
        el.append(c instanceof Node ? c : String(c));
    }
}

export function h<K extends keyof HTMLElementTagNameMap>(tag: K, attrs: Attrs = {}, ...children: Child[]): HTMLElementTagNameMap[K] {
    const el = document.createElement(tag);
    apply(el, attrs);
    append(el, children);
    return el;
}

const SVG_NS = 'http://www.w3.org/2000/svg';

export function s<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Attrs = {}, ...children: Child[]): SVGElementTagNameMap[K] {
    const el = document.createElementNS(SVG_NS, tag);
    apply(el, attrs);
    append(el, children);
    return el;
}

/** Offers text as a file download. */
export function downloadText(filename: string, text: string, type = 'text/plain'): void {
    downloadBlob(filename, new Blob([text], { type }));
}

export function downloadBlob(filename: string, blob: Blob): void {
    const url = URL.createObjectURL(blob);
    const a = h('a', { href: url, download: filename });
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** A short message at the bottom of the window. */
export function toast(message: string, kind: 'info' | 'error' = 'info'): void {
    let box = document.getElementById('toasts');
    if (!box) {
        box = h('div', { id: 'toasts' });
        document.body.append(box);
    }
    // the same message twice at once says nothing new
    if ([...box.children].some((c) => c.textContent === message)) return;
    const item = h('div', { class: `toast toast-${kind}`, role: kind === 'error' ? 'alert' : 'status' }, message);
    box.append(item);
    setTimeout(() => item.remove(), kind === 'error' ? 8000 : 4000);
}

/** An error's message as the user reads it: server validation paths and type names in words (errorWords.ts). */
export function errorText(e: unknown): string {
    return inWords(e instanceof Error ? e.message : String(e));
}
