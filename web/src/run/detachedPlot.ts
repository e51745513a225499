// A plot window in a browser window of its own. This page keeps the data and the live stream;
// the plot's elements move into an empty popup of the same origin and are drawn there as before
// (the popup has the page's style sheets, and its Content Security Policy, from its opener).
// Closing the popup, or leaving this page, gives the plot back.

export interface Detached {
    /** Closes the popup (the plot is given back through `onClosed`). */
    close(): void;
}

/**
 * Moves `element` into a new popup titled `title`; `onClosed` is told once when the popup
 * goes (before the element is lost with it). Null when the browser blocked the popup.
 */
export function detach(element: HTMLElement, title: string, onClosed: () => void): Detached | null {
    const { width, height } = element.getBoundingClientRect();
    const popup = window.open('', '_blank', `popup,width=${Math.max(640, Math.round(width))},height=${Math.max(420, Math.round(height) + 40)}`);
    if (!popup) return null;
    const doc = popup.document;
    doc.title = title;
    for (const sheet of document.querySelectorAll('link[rel="stylesheet"], style')) doc.head.append(doc.importNode(sheet, true));
    doc.body.classList.add('detached-body');
    doc.body.append(element);
    // uPlot ends a drag-to-zoom on its own page's mouseup; the popup's is passed on to it
    doc.addEventListener('mouseup', (e) => document.dispatchEvent(new MouseEvent('mouseup', e)));

    let open = true;
    const closed = () => {
        if (!open) return;
        open = false;
        window.removeEventListener('pagehide', close);
        onClosed();
    };
    const close = () => {
        closed();
        popup.close();
    };
    popup.addEventListener('pagehide', closed);
    // a popup left open would show a plot that no longer streams
    window.addEventListener('pagehide', close);
    return { close };
}
