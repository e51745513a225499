// The entries of the editor's context menus: on a component (or the selection it is part of),
// on a connection line, on a port and on the empty canvas. Each entry runs an EditorActions
// action (the same as the key shown beside it), so every change is one undoable command; an
// entry whose kind of change the open model does not allow (a locked copy) is disabled.
import type { MenuEntry, MenuItem } from './ContextMenu';
import type { EditorActions, EditKind } from './EditorActions';
import type { EditorStore } from './EditorStore';
import type { CanvasTarget, CanvasView } from './CanvasView';
import { keysOf } from './shortcuts';
import { planSummary, portShapeOfCatalogue, replacementPlan } from './replaceType';
import { hiddenUnlessShown, isParameterPort } from '../model/parameterPortPlacement';
import { portVariables } from '../model/variables';
import { primaryVariables } from '../model/nodeTypes';
import { displayNameOf } from '../model/appearance';
import { connectionsOf } from '../model/modelState';
import { addCorner, cornerAt, removeCorner } from './lineRouting';
import type { Point } from '../model/geometry';
import type { PortRef } from '../protocol/types';

export interface MenuContext {
    actions: EditorActions;
    store: EditorStore;
    canvas: CanvasView;
    /** Adds a logged variable to the active plot window. */
    plot(variable: string, label: string, unit: string): void;
    showHelp(): void;
    /** Puts a live control bound to one of the component's values on the drawing (src/live/). */
    addLiveControl?(component: string): void;
}

/** An entry that changes the model: disabled where that kind of change is not allowed. */
function edit(ctx: MenuContext, kind: EditKind, entry: MenuEntry): MenuEntry {
    const own = entry.disabled;
    return { ...entry, disabled: () => !ctx.actions.may(kind) || (own?.() ?? false) };
}

/** The menu for what was right-clicked, with the name screen readers announce. */
export function menuFor(ctx: MenuContext, target: CanvasTarget): { items: MenuItem[]; label: string } {
    switch (target.kind) {
    case 'component': return { items: componentMenu(ctx, target.name), label: `${target.name} menu` };
    case 'connection': return { items: connectionMenu(ctx, target.from, target.to, target.at), label: 'Connection menu' };
    case 'port': return { items: portMenu(ctx, target.ref), label: `${target.ref.component}.${target.ref.port} menu` };
    case 'canvas': return { items: canvasMenu(ctx, target.at), label: 'Canvas menu' };
    }
}

/** A port's logged variables, each an entry that plots it (the primary ones first). */
export function plotEntries(ctx: MenuContext, ref: PortRef): MenuItem[] {
    const vars = portVariables(ctx.store.model, ctx.store.path, ref);
    if (!vars.ok) return [{ label: `Nothing to plot: ${vars.reason}`, disabled: () => true }];
    const ordered = [...vars.variables].sort((a, b) => Number(primaryVariables.has(b.name)) - Number(primaryVariables.has(a.name)));
    return ordered.map((v) => ({
        label: `Plot ${v.name}${v.unit ? ` [${v.unit}]` : ''}`,
        id: `plot-${v.name}`,
        run: () => ctx.plot(`${vars.base}#${v.name}`, `${vars.label} ${v.name}`, v.unit),
    }));
}

export function componentMenu(ctx: MenuContext, name: string): MenuItem[] {
    const { actions, store, canvas } = ctx;
    const comp = store.system.components.find((c) => c.name === name);
    if (!comp) return [];
    const selected = actions.selected();
    const many = selected.length > 1;
    const withParameterPorts = selected.filter((c) => c.ports.some((p) => isParameterPort(c, p)));
    const portsShown = withParameterPorts.length > 0 && withParameterPorts.every((c) => canvas.parameterPorts.shownFor(store.path, c.name));
    const namesHidden = selected.every((c) => canvas.names.hiddenFor(store.path, c.name));
    const items: MenuItem[] = [];
    if (!many) {
        if (comp.system) items.push({ label: 'Enter subsystem', shortcut: keysOf('open'), id: 'enter', run: () => actions.enter(name) });
        items.push({ label: 'Parameters…', shortcut: comp.system ? undefined : keysOf('open'), id: 'parameters', run: () => actions.openParameters(name) });
        items.push({
            label: 'Plot variables', id: 'plot',
            submenu: () => comp.ports.filter((p) => (!p.multiport || p.connected) && !hiddenUnlessShown(comp, p)).map((p) => ({
                label: `${p.name} (${p.node_type.replace(/^Node/, '').toLowerCase()} ${p.kind})`, id: `plot-port-${p.name}`,
                submenu: () => plotEntries(ctx, { component: name, port: p.name }),
            })),
        });
        const addLiveControl = ctx.addLiveControl;
        if (addLiveControl && !comp.system) {
            items.push(edit(ctx, 'system-parameters', { label: 'Add live control…', id: 'add-live-control', run: () => addLiveControl(name) }));
        }
        items.push('separator');
    }
    items.push(
        edit(ctx, 'rotate', { label: 'Rotate right', shortcut: keysOf('rotate-right'), id: 'rotate-right', run: () => void actions.rotate(1) }),
        edit(ctx, 'rotate', { label: 'Rotate left', shortcut: keysOf('rotate-left'), id: 'rotate-left', run: () => void actions.rotate(-1) }),
        edit(ctx, 'flip', { label: 'Flip horizontally', shortcut: keysOf('flip-horizontal'), id: 'flip-horizontal', run: () => void actions.flip('horizontal') }),
        edit(ctx, 'flip', { label: 'Flip vertically', shortcut: keysOf('flip-vertical'), id: 'flip-vertical', run: () => void actions.flip('vertical') }),
        'separator',
    );
    if (withParameterPorts.length > 0) {
        items.push({
            label: portsShown ? 'Hide parameter ports' : 'Show parameter ports', shortcut: keysOf('parameter-ports'), id: 'parameter-ports',
            hint: 'The small triangles of the settable inputs, hidden until shown', run: () => actions.toggleParameterPorts(),
        });
    }
    items.push(
        { label: namesHidden ? 'Show name' : 'Hide name', shortcut: keysOf('names'), id: 'name', run: () => actions.toggleNames() },
        'separator',
        {
            label: 'Copy', shortcut: keysOf('copy'), id: 'copy', run: () => void actions.copy(),
            disabled: () => selected.every((c) => c.system), hint: selected.every((c) => c.system) ? 'Subsystems cannot be copied yet' : undefined,
        },
        edit(ctx, 'delete', { label: 'Cut', shortcut: keysOf('cut'), id: 'cut', run: () => void actions.cut(), disabled: () => selected.every((c) => c.system) }),
        edit(ctx, 'delete', { label: 'Delete', shortcut: keysOf('delete'), id: 'delete', run: () => void actions.remove() }),
        'separator',
        edit(ctx, 'group', { label: 'Group into subsystem', shortcut: keysOf('group'), id: 'group', run: () => void actions.group() }),
    );
    if (!many && comp.system) items.push(edit(ctx, 'ungroup', { label: 'Ungroup', id: 'ungroup', run: () => void actions.ungroup(name) }));
    if (!many && !comp.system) {
        const types = actions.replacementsFor(name);
        items.push(edit(ctx, 'replace', {
            label: 'Replace with', id: 'replace',
            hint: types.length ? 'Another type with the same power ports: keeps the connections and the parameters of the same name' : 'No other type has the same power ports',
            disabled: () => types.length === 0,
            submenu: () => {
                const lines = connectionsOf(store.system, name);
                return types.map((t) => {
                    const plan = replacementPlan(comp, lines, t.ports.map(portShapeOfCatalogue), t.parameters);
                    return {
                        label: displayNameOf(t.type), id: `replace-${t.type}`, hint: `${t.type}: ${planSummary(plan)}`,
                        run: () => void actions.replace(name, t.type),
                    };
                });
            },
        }));
    }
    return items;
}

/** `at`: where on the line the menu was opened (a corner is added there, or the one there removed). */
export function connectionMenu(ctx: MenuContext, from: PortRef, to: PortRef, at: Point): MenuItem[] {
    const path = ctx.canvas.linePath(from, to);
    const corner = path ? cornerAt(path, at, ctx.canvas.sceneDistance(8)) : null;
    return [
        edit(ctx, 'lines', {
            label: 'Add corner here', id: 'add-corner', disabled: () => !path,
            run: () => void ctx.actions.reshapeLine(from, to, 'Add corner', (p) => addCorner(p, at)),
        }),
        edit(ctx, 'lines', {
            label: 'Remove corner', id: 'remove-corner', disabled: () => corner === null,
            hint: corner === null ? 'Right click on a corner of the line' : undefined,
            run: () => void ctx.actions.reshapeLine(from, to, 'Remove corner', (p) => (corner === null ? p : removeCorner(p, corner))),
        }),
        'separator',
        edit(ctx, 'disconnect', {
            label: 'Delete connection', shortcut: keysOf('delete'), id: 'delete',
            hint: `${from.component}.${from.port} – ${to.component}.${to.port}`,
            run: () => {
                ctx.canvas.selectedConnection = { from, to };
                void ctx.actions.remove();
            },
        }),
        'separator',
        { label: `Plot ${from.component}.${from.port}`, id: 'plot-from', submenu: () => plotEntries(ctx, from) },
        { label: `Plot ${to.component}.${to.port}`, id: 'plot-to', submenu: () => plotEntries(ctx, to) },
    ];
}

export function portMenu(ctx: MenuContext, ref: PortRef): MenuItem[] {
    return plotEntries(ctx, ref);
}

export function canvasMenu(ctx: MenuContext, at: Point): MenuItem[] {
    const { actions, canvas } = ctx;
    const shownEverywhere = canvas.parameterPorts.shownEverywhere;
    return [
        edit(ctx, 'paste', { label: 'Paste here', shortcut: keysOf('paste'), id: 'paste', disabled: () => !actions.canPaste, run: () => void actions.paste(at) }),
        { label: 'Select all', shortcut: keysOf('select-all'), id: 'select-all', run: () => actions.selectAll() },
        'separator',
        { label: 'Zoom to fit', shortcut: keysOf('fit'), id: 'fit', run: () => actions.fit() },
        {
            label: shownEverywhere ? 'Hide all parameter ports' : 'Show all parameter ports', shortcut: keysOf('all-parameter-ports'),
            id: 'all-parameter-ports', checked: shownEverywhere, run: () => actions.toggleAllParameterPorts(),
        },
        'separator',
        { label: 'Keyboard shortcuts…', shortcut: keysOf('help'), id: 'help', run: () => ctx.showHelp() },
    ];
}
