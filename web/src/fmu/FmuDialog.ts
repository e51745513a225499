// "Download FMU": shows the interface the stored model's FMU has (GET /models/{id}/fmu/interface),
// lets the user offer component parameters as FMU parameters and name the FMU, and downloads it.
import type { RestClient, FmuOptions } from '../api/RestClient';
import { downloadBlob, errorText, h } from '../ui/dom';
import { parameterList } from './fmuInterface';
import { renderFmuInterface } from './FmuInterfaceView';

export interface FmuDialogModel {
    id: number;
    unsaved: boolean;   // the editor has changes the stored model (what is exported) lacks
}

type FmuRest = Pick<RestClient, 'fmuInterface' | 'downloadFmu'>;

/** The dialog's content; `close` ends it. Resolves once the first interface is shown. */
export function fmuDialogContent(rest: FmuRest, model: FmuDialogModel, close: () => void): { element: HTMLElement; ready: Promise<void> } {
    const parameters = h('textarea', { rows: 2, placeholder: 'Gain.k, Mass.m', 'data-testid': 'fmu-parameters-input' });
    const identifier = h('input', { placeholder: 'from the model name', 'data-testid': 'fmu-identifier-input' });
    const error = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'fmu-error' });
    const body = h('div', { class: 'fmu-body', 'data-testid': 'fmu-interface' }, h('p', { class: 'muted' }, 'Reading the interface…'));
    const downloadButton = h('button', { class: 'primary', disabled: true, 'data-testid': 'fmu-download' }, 'Download');
    let fileName = '';
    const options = (): FmuOptions => ({ parameters: parameterList(parameters.value), identifier: identifier.value.trim() || undefined });

    // The interface for the options as they are; the download stays off while they do not give one.
    const refresh = async () => {
        downloadButton.disabled = true;
        error.textContent = '';
        try {
            const iface = await rest.fmuInterface(model.id, options());
            fileName = `${iface.model_identifier}.fmu`;
            body.replaceChildren(renderFmuInterface(iface));
            downloadButton.disabled = false;
        } catch (e) {
            error.textContent = errorText(e);
        }
    };
    downloadButton.addEventListener('click', async () => {
        downloadButton.disabled = true;
        error.textContent = '';
        try {
            downloadBlob(fileName, await rest.downloadFmu(model.id, options()));
        } catch (e) {
            error.textContent = errorText(e);
        } finally {
            downloadButton.disabled = false;
        }
    });

    const element = h('div', { class: 'fmu-dialog-content' },
        h('h2', {}, 'Download FMU'),
        model.unsaved
            ? h('p', { class: 'fmu-unsaved', 'data-testid': 'fmu-unsaved' }, 'The saved version of the model is exported: save first to include your unsaved changes.')
            : '',
        body,
        h('div', { class: 'fmu-options' },
            h('label', {}, 'Component parameters to offer (Comp.param, comma or line separated)', parameters),
            h('label', {}, 'Model identifier', identifier),
            h('button', { onclick: () => void refresh(), 'data-testid': 'fmu-refresh' }, 'Refresh')),
        error,
        h('div', { class: 'fmu-actions' }, h('button', { onclick: close }, 'Close'), downloadButton));
    return { element, ready: refresh() };
}

/** Opens the dialog over the page; it removes itself when closed. */
export function openFmuDialog(rest: FmuRest, model: FmuDialogModel): void {
    const dialog = h('dialog', { class: 'fmu-dialog', 'data-testid': 'fmu-dialog', 'aria-label': 'Download FMU' });
    const { element } = fmuDialogContent(rest, model, () => dialog.close());
    dialog.append(element);
    dialog.addEventListener('close', () => dialog.remove());
    document.body.append(dialog);
    dialog.showModal();
}
