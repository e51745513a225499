// A form in a modal <dialog>, shown until the user submits or cancels: the promise gives what
// `read` makes of the form, or null for Cancel or Escape. `read` returns undefined to keep the
// dialog open (it has shown why, e.g. a value out of range).
export function runModalForm<T>(dialog: HTMLDialogElement, form: HTMLFormElement, cancel: HTMLElement,
    read: () => T | undefined, focus: HTMLElement): Promise<T | null> {
    document.body.append(dialog);
    return new Promise((resolve) => {
        const finish = (result: T | null) => {
            dialog.close();
            dialog.remove();
            resolve(result);
        };
        cancel.addEventListener('click', () => finish(null));
        dialog.addEventListener('cancel', () => finish(null));
        form.addEventListener('submit', (e) => {
            e.preventDefault();
            const result = read();
            if (result !== undefined) finish(result);
        });
        dialog.showModal();
        focus.focus();
    });
}
