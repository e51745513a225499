// What the editor's keys, toolbar, parameter panel and context menus do. Every change is one
// command run through the store, so the same action is one undo step from wherever it was
// started; a refusal goes to the editor's message area.
import type { EditorStore } from './EditorStore';
import type { CanvasView } from './CanvasView';
import {
    copySelection, Disconnect, flippedPose, GroupComponents, MoveComponents, offsetTo, Paste, RemoveComponents,
    ReplaceComponent, rotatedPose, RouteConnection, UngroupSubsystem, type Clipboard, type Command,
} from './commands';
import { routePoints } from './lineRouting';
import { joins } from '../model/modelState';
import { replacementTypes } from './replaceType';
import { displayNameOf } from '../model/appearance';
import type { CatalogueEntry, Component, PortRef, Pose } from '../protocol/types';
import type { Point } from '../model/geometry';

/**
 * The kinds of change an action makes, as EditPermissions names them: a locked copy
 * (`allows` false) offers the action disabled.
 */
export type EditKind = 'add' | 'delete' | 'move' | 'rotate' | 'flip' | 'connect' | 'disconnect' | 'rename'
    | 'group' | 'ungroup' | 'paste' | 'replace' | 'lines' | 'system-parameters' | 'settings';

export interface ActionHost {
    readonly store: EditorStore;
    readonly canvas: CanvasView;
    /** The component types the server knows (GET /components). */
    readonly catalogue: CatalogueEntry[];
    /** A refused or failed action: shown in the message area. */
    report(e: unknown): void;
    /** What an action did, when it is worth saying. */
    note(message: string): void;
    /** Opens the parameter panel on a component. */
    openParameters(name: string): void;
    /** Whether this kind of change may be made (a locked copy allows few); all when absent. */
    allows?(edit: EditKind): boolean;
}

// one clipboard for every editor page of the tab: copied in one model, pasted in another
let clipboard: Clipboard | null = null;

export class EditorActions {
    constructor(private readonly host: ActionHost) {}

    private get store(): EditorStore { return this.host.store; }

    /** Whether `edit` may be made in the open model. */
    may(edit: EditKind): boolean {
        return this.host.allows?.(edit) ?? true;
    }

    /** The selected components, in the system's order. */
    selected(): Component[] {
        return this.store.system.components.filter((c) => this.store.selection.has(c.name));
    }

    /** Runs a command; resolves true when the server took it, else shows why. */
    async run(command: Command): Promise<boolean> {
        try {
            await this.store.execute(command);
            return true;
        } catch (e) {
            this.host.report(e);
            return false;
        }
    }

    private transform(label: string, change: (p: Pose) => Pose): Promise<boolean> {
        const moves = this.selected().map((c) => ({ name: c.name, from: c.pose, to: change({ ...c.pose }) }));
        if (moves.length === 0) return Promise.resolve(false);
        return this.run(new MoveComponents(this.store.path, moves, label));
    }

    /** Reshapes the line between two ports: `change` turns the drawn path (from the connection's `from`) into the new one. */
    reshapeLine(a: PortRef, b: PortRef, label: string, change: (path: Point[]) => Point[]): Promise<boolean> {
        const line = this.store.system.connections.find((c) => joins(c, a, b));
        const path = line && this.host.canvas.linePath(line.from, line.to);
        if (!line || !path) return Promise.resolve(false);
        return this.run(new RouteConnection(this.store.path, line.from, line.to, line.points, routePoints(change(path)), label));
    }

    /** Turns the selection a quarter clockwise (1, "rotate right") or anticlockwise (-1). */
    rotate(quarterTurns: 1 | -1 = 1): Promise<boolean> {
        return this.transform(quarterTurns === 1 ? 'Rotate right' : 'Rotate left', (p) => rotatedPose(p, quarterTurns));
    }

    flip(axis: 'horizontal' | 'vertical' = 'horizontal'): Promise<boolean> {
        return this.transform(axis === 'horizontal' ? 'Flip horizontally' : 'Flip vertically', (p) => flippedPose(p, axis));
    }

    /** Deletes the selected line, else the selected components. */
    async remove(): Promise<boolean> {
        const line = this.host.canvas.selectedConnection;
        if (line) {
            this.host.canvas.selectedConnection = null;
            return this.run(new Disconnect(this.store.path, line.from, line.to));
        }
        const names = [...this.store.selection];
        if (names.length === 0) return false;
        return this.run(new RemoveComponents(this.store.path, names));
    }

    get canPaste(): boolean { return clipboard !== null; }

    /** Copies the selected components (not subsystems) with the connections among them. */
    copy(): boolean {
        const copied = copySelection(this.store.model, this.store.path, this.store.selection);
        if (!copied) {
            if (this.selected().some((c) => c.system)) this.host.note('Subsystems cannot be copied yet');
            return false;
        }
        clipboard = copied;
        return true;
    }

    /** Copy, then delete: two steps, of which undo takes back the delete. */
    async cut(): Promise<boolean> {
        if (!this.copy()) return false;
        return this.remove();
    }

    /** Pastes the clipboard a little off the copied place, or centred at `at` (scene coordinates). */
    async paste(at?: Point): Promise<boolean> {
        if (!clipboard) return false;
        const command = new Paste(this.store.path, clipboard, at ? offsetTo(clipboard, at) : 40);
        if (!await this.run(command)) return false;
        this.store.select(command.addedNames);
        return true;
    }

    selectAll(): void {
        this.host.canvas.selectedConnection = null;
        this.store.select(this.store.system.components.map((c) => c.name));
    }

    async group(): Promise<boolean> {
        const names = this.selected().map((c) => c.name);
        if (names.length === 0) return false;
        const command = new GroupComponents(this.store.path, names);
        if (!await this.run(command)) return false;
        this.store.select([command.subsystemName]);
        this.host.note(`Grouped ${names.length} component${names.length === 1 ? '' : 's'} into ${command.subsystemName}`);
        return true;
    }

    async ungroup(name = this.selected().find((c) => c.system)?.name): Promise<boolean> {
        if (!name) return false;
        const command = new UngroupSubsystem(this.store.path, name);
        if (!await this.run(command)) return false;
        this.store.select(command.movedNames);
        return true;
    }

    /** Shows the inside of a subsystem. */
    enter(name: string): void {
        this.store.enterSystem([...this.store.path, name]);
    }

    /** The types that may take the component's place (replaceType.ts). */
    replacementsFor(name: string): CatalogueEntry[] {
        const comp = this.store.system.components.find((c) => c.name === name);
        return comp ? replacementTypes(comp, this.host.catalogue) : [];
    }

    /** Puts a component of `type` in the place of `name` (one undo step). */
    async replace(name: string, type: string): Promise<boolean> {
        const command = new ReplaceComponent(this.store.path, name, type);
        if (!await this.run(command)) return false;
        this.store.select([command.newName]);
        const dropped = command.droppedConnections;
        if (dropped.length > 0) {
            this.host.note(`${displayNameOf(type)} has no port for ${dropped.length} of the connections: they were removed (Ctrl+Z brings them back)`);
        }
        return true;
    }

    /** Shows or hides the parameter ports of the selected components. */
    toggleParameterPorts(names = [...this.store.selection]): void {
        this.host.canvas.parameterPorts.toggle(this.store.path, names);
    }

    /** Shows or hides every component's parameter ports. */
    toggleAllParameterPorts(): void {
        const ports = this.host.canvas.parameterPorts;
        ports.showEverywhere(!ports.shownEverywhere);
    }

    /** Shows or hides the selected components' names. */
    toggleNames(names = [...this.store.selection]): void {
        this.host.canvas.names.toggle(this.store.path, names);
    }

    openParameters(name: string): void {
        this.store.select([name]);
        this.host.openParameters(name);
    }

    fit(): void {
        this.host.canvas.fit();
    }
}
