// The editor's message area: why an edit was refused ("Cannot connect Step.out to
// 4_3_Servo_Valve.PT: a signal port cannot be joined to a hydraulic port …"), in an HTML box
// laid over the top of the canvas. Unlike a text drawn in the SVG it wraps and is never cut
// off by the canvas's edge; it is announced to screen readers (role alert), stays until
// closed, replaced or a while has passed, and keeps the last few messages when they come fast.
import { errorText, h } from '../ui/dom';

const KEPT = 3;
const ERROR_MS = 15000;
const NOTE_MS = 6000;

export type MessageKind = 'error' | 'note';

/** `text` as a sentence: a capital first letter and a full stop. */
export function asSentence(text: string): string {
    const t = text.trim();
    if (!t) return t;
    const capital = t.charAt(0).toUpperCase() + t.slice(1);
    return /[.!?)]$/.test(capital) ? capital : `${capital}.`;
}

export class MessageArea {
    readonly element = h('div', { class: 'editor-messages', 'data-testid': 'editor-messages', 'aria-live': 'polite' });
    private readonly timers = new Map<HTMLElement, ReturnType<typeof setTimeout>>();

    /** Shows an error (an Error, an ApiError or a text) in words. */
    error(e: unknown): void {
        this.show(errorText(e), 'error');
    }

    note(text: string): void {
        this.show(text, 'note');
    }

    show(text: string, kind: MessageKind): void {
        const message = asSentence(text);
        // the same message again says nothing new: it only stays longer
        const same = [...this.element.children].find((c) => (c as HTMLElement).dataset.text === message) as HTMLElement | undefined;
        if (same) {
            this.arm(same, kind);
            return;
        }
        const close = h('button', { class: 'editor-message-close', 'aria-label': 'Dismiss the message', title: 'Dismiss' }, '×');
        const item = h('div', {
            class: `editor-message editor-message-${kind}`, role: kind === 'error' ? 'alert' : 'status',
            dataset: { text: message },
        }, h('span', { class: 'editor-message-text' }, message), close);
        close.addEventListener('click', () => this.remove(item));
        this.element.append(item);
        while (this.element.children.length > KEPT) this.remove(this.element.firstElementChild as HTMLElement);
        this.arm(item, kind);
    }

    /** The messages shown, oldest first (for tests). */
    get texts(): string[] {
        return [...this.element.children].map((c) => (c as HTMLElement).dataset.text ?? '');
    }

    clear(): void {
        for (const c of [...this.element.children]) this.remove(c as HTMLElement);
    }

    dispose(): void {
        this.clear();
    }

    private arm(item: HTMLElement, kind: MessageKind): void {
        clearTimeout(this.timers.get(item));
        this.timers.set(item, setTimeout(() => this.remove(item), kind === 'error' ? ERROR_MS : NOTE_MS));
    }

    private remove(item: HTMLElement): void {
        clearTimeout(this.timers.get(item));
        this.timers.delete(item);
        item.remove();
    }
}
