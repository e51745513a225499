import { describe, expect, it } from 'vitest';
import { canvasMenu, componentMenu, connectionMenu } from './editorMenus';
import { EditorActions, type EditKind } from './EditorActions';
import { EditorStore } from './EditorStore';
import { AddComponent, Connect } from './commands';
import { ParameterPortVisibility } from './ParameterPortVisibility';
import { NameVisibility } from './NameVisibility';
import { SHORTCUTS, shortcutFor } from './shortcuts';
import { FakeServer, fakeCatalogue } from '../testing/FakeServer';
import type { CanvasView } from './CanvasView';
import type { MenuEntry, MenuItem } from './ContextMenu';
import type { CatalogueEntry } from '../protocol/types';

const catalogue: CatalogueEntry[] = Object.entries(fakeCatalogue).map(([type, info]) => ({
    type, kind: info.kind as CatalogueEntry['kind'], domain: '',
    ports: info.ports.map(([name, kind, nodetype]) => ({
        name, nodetype, porttype: kind === 'power' ? 'PowerPort' : kind === 'read' ? 'ReadPort' : 'WritePort', required: false, description: '',
    })),
    parameters: info.params.map(([name, value]) => ({ name, default: value, type: 'double' as const, unit: '', description: '' })),
}));

async function editor(allowed: (edit: EditKind) => boolean = () => true) {
    const server = new FakeServer();
    const store = new EditorStore(structuredClone(server.model), server.handle);
    await store.execute(new AddComponent([], 'Hydraulic43Valve', 'Valve', { x: 0, y: 0, angle: 0, flipped: false }));
    await store.execute(new AddComponent([], 'HydraulicTankC', 'Tank', { x: 0, y: 80, angle: 0, flipped: false }));
    await store.execute(new Connect([], { component: 'Tank', port: 'P1' }, { component: 'Valve', port: 'PT' }));
    // the Tank-Valve line as drawn: from Tank.P1 up to Valve.PT, with two corners
    const line = [{ x: 0, y: 80 }, { x: 40, y: 80 }, { x: 40, y: 20 }, { x: 0, y: 20 }];
    const canvas = {
        parameterPorts: new ParameterPortVisibility(), names: new NameVisibility(), selectedConnection: null, fit: () => undefined,
        linePath: () => line, sceneDistance: (pixels: number) => pixels,
    } as unknown as CanvasView;
    const notes: string[] = [];
    const actions = new EditorActions({
        store, canvas, catalogue, report: (e) => notes.push(String(e)), note: (m) => notes.push(m),
        openParameters: () => undefined, allows: allowed,
    });
    const ctx = { actions, store, canvas, plot: () => undefined, showHelp: () => undefined };
    store.select(['Valve']);
    return { store, ctx, notes };
}

const entries = (items: MenuItem[]) => items.filter((i): i is MenuEntry => i !== 'separator');
const byId = (items: MenuItem[], id: string) => entries(items).find((e) => e.id === id)!;
const enabled = (e: MenuEntry) => !(e.disabled?.() ?? false);

describe('the editor\'s context menus', () => {
    it('a component\'s menu has the entries the issue asks for, with the keys of the shortcut table', async () => {
        const { ctx } = await editor();
        const items = componentMenu(ctx, 'Valve');
        expect(entries(items).map((e) => e.id)).toEqual([
            'parameters', 'plot', 'rotate-right', 'rotate-left', 'flip-horizontal', 'flip-vertical', 'parameter-ports', 'name',
            'copy', 'cut', 'delete', 'group', 'replace',
        ]);
        expect(byId(items, 'rotate-right').shortcut).toBe('R');
        expect(byId(items, 'rotate-left').shortcut).toBe('Shift+R');
        expect(byId(items, 'delete').shortcut).toBe('Del');
        const replace = entries(byId(items, 'replace').submenu!());
        expect(replace.map((e) => e.id)).toEqual(['replace-Hydraulic43ValveNeutralToTank']);
        expect(replace[0].hint).toContain('keeps its connection');
    });

    it('a menu entry runs the same undoable command as the key', async () => {
        const { ctx, store } = await editor();
        byId(componentMenu(ctx, 'Valve'), 'rotate-right').run!();
        await store.idle();
        expect(store.system.components[0].pose.angle).toBe(90);
        expect(store.history.undoLabel).toBe('Rotate right');
        byId(componentMenu(ctx, 'Valve'), 'flip-vertical').run!();
        await store.idle();
        expect(store.system.components[0].pose).toMatchObject({ angle: 270, flipped: true });
        await store.undo();
        await store.undo();
        expect(store.system.components[0].pose).toMatchObject({ angle: 0, flipped: false });
    });

    it('replace from the menu keeps the connection and undoes in one step', async () => {
        const { ctx, store } = await editor();
        entries(byId(componentMenu(ctx, 'Valve'), 'replace').submenu!())[0].run!();
        await store.idle();
        expect(store.system.components.find((c) => c.name === 'Valve')!.type).toBe('Hydraulic43ValveNeutralToTank');
        expect(store.system.connections.map((c) => `${c.to.component}.${c.to.port}`)).toEqual(['Valve.PT']);
        await store.undo();
        expect(store.system.components.find((c) => c.name === 'Valve')!.type).toBe('Hydraulic43Valve');
        expect(store.system.connections).toHaveLength(1);
    });

    it('where a kind of change is not allowed (a locked copy), its entries are disabled; looking and plotting stay', async () => {
        const { ctx } = await editor(() => false);
        const items = componentMenu(ctx, 'Valve');
        for (const id of ['rotate-right', 'rotate-left', 'flip-horizontal', 'flip-vertical', 'cut', 'delete', 'group', 'replace']) {
            expect(enabled(byId(items, id)), id).toBe(false);
        }
        for (const id of ['parameters', 'plot', 'parameter-ports', 'name', 'copy']) expect(enabled(byId(items, id)), id).toBe(true);
        const lineMenu = connectionMenu(ctx, { component: 'Tank', port: 'P1' }, { component: 'Valve', port: 'PT' }, { x: 40, y: 21 });
        for (const id of ['delete', 'add-corner', 'remove-corner']) expect(enabled(byId(lineMenu, id)), id).toBe(false);
        expect(enabled(byId(canvasMenu(ctx, { x: 0, y: 0 }), 'select-all'))).toBe(true);
    });

    it('the canvas menu pastes only with something copied, at the pointer', async () => {
        const { ctx, store } = await editor();
        // (the clipboard is the tab's: another test may have filled it)
        const paste = () => byId(canvasMenu(ctx, { x: 300, y: 300 }), 'paste');
        ctx.actions.copy();
        expect(enabled(paste())).toBe(true);
        paste().run!();
        await store.idle();
        const pasted = store.system.components.find((c) => c.name === 'Valve_1')!;
        expect(pasted.pose).toMatchObject({ x: 300, y: 300 });
    });

    it('a line\'s menu adds a corner where it was opened and removes the corner there, each one undo step', async () => {
        const { ctx, store } = await editor();
        const tank = { component: 'Tank', port: 'P1' };
        const valve = { component: 'Valve', port: 'PT' };
        const points = () => store.system.connections[0].points;
        const away = connectionMenu(ctx, tank, valve, { x: 20, y: 50 });
        expect(enabled(byId(away, 'add-corner'))).toBe(true);
        expect(enabled(byId(away, 'remove-corner'))).toBe(false);   // no corner near there
        // opened from the Valve end: the points still run from the connection's own "from"
        byId(connectionMenu(ctx, valve, tank, { x: 20, y: 81 }), 'add-corner').run!();
        await store.idle();
        expect(points()).toEqual([[0, 80], [20, 80], [40, 80], [40, 20], [0, 20]]);
        expect(store.history.undoLabel).toBe('Add corner');
        byId(connectionMenu(ctx, tank, valve, { x: 40, y: 21 }), 'remove-corner').run!();
        await store.idle();
        expect(points()).toEqual([[0, 80], [40, 80], [0, 20]]);
        await store.undo();
        expect(points()).toEqual([[0, 80], [20, 80], [40, 80], [40, 20], [0, 20]]);
        await store.undo();
        expect(points()).toEqual([]);
    });

    it('names and all parameter ports are toggled from the menus', async () => {
        const { ctx } = await editor();
        byId(componentMenu(ctx, 'Valve'), 'name').run!();
        expect(ctx.canvas.names.hiddenFor([], 'Valve')).toBe(true);
        expect(byId(componentMenu(ctx, 'Valve'), 'name').label).toBe('Show name');
        byId(canvasMenu(ctx, { x: 0, y: 0 }), 'all-parameter-ports').run!();
        expect(ctx.canvas.parameterPorts.shownEverywhere).toBe(true);
        expect(byId(canvasMenu(ctx, { x: 0, y: 0 }), 'all-parameter-ports').label).toBe('Hide all parameter ports');
    });
});

describe('the shortcut table', () => {
    const key = (k: string, init: Partial<KeyboardEvent> = {}) => ({ key: k, ctrlKey: false, metaKey: false, altKey: false, shiftKey: false, ...init }) as KeyboardEvent;

    it('names every key once and tells keys apart by Shift', () => {
        expect(new Set(SHORTCUTS.map((s) => s.keys)).size).toBe(SHORTCUTS.length);
        expect(shortcutFor(key('r'), 'canvas')?.id).toBe('rotate-right');
        expect(shortcutFor(key('R', { shiftKey: true }), 'canvas')?.id).toBe('rotate-left');
        expect(shortcutFor(key('F', { shiftKey: true }), 'canvas')?.id).toBe('flip-vertical');
        expect(shortcutFor(key('z', { ctrlKey: true }), 'canvas')?.id).toBe('undo');
        expect(shortcutFor(key('?', { shiftKey: true }), 'canvas')?.id).toBe('help');
        expect(shortcutFor(key('F10', { shiftKey: true }), 'canvas')?.id).toBe('menu');
    });

    it('keys typed into a field are the field\'s, but Ctrl+S; Enter on a button is the button\'s', () => {
        expect(shortcutFor(key('r'), 'field')).toBeNull();
        expect(shortcutFor(key('s', { ctrlKey: true }), 'field')?.id).toBe('save');
        expect(shortcutFor(key('Enter'), 'control')).toBeNull();
        expect(shortcutFor(key('Enter'), 'canvas')?.id).toBe('open');
    });
});
