// @vitest-environment jsdom
// The rule "what may be edited in this model": a locked copy takes only the listed parameters
// within their bounds (as the server's ParameterLock), refuses every other edit before it is
// sent, and its parameter panel shows that: read-only fields, bounds beside the allowed ones,
// a refused value back at the last good one with the reason.
import { describe, expect, it } from 'vitest';
import { EditPermissions, parameterPath, permittedTransport } from './EditPermissions';
import { EditorStore } from './EditorStore';
import { AddComponent, MoveComponents, SetParameter, SetSystemParameter } from './commands';
import { ParameterPanel, type PanelActions } from './ParameterPanel';
import { FakeServer } from '../testing/FakeServer';
import type { Assignment } from '../labs/types';

const at = (x: number, y: number) => ({ x, y, angle: 0, flipped: false });
const locked = EditPermissions.lockedTo([{ name: 'Gain.k', min: 0, max: 0.1 }, { name: 'Sub$Mass.m' }, { name: 'gain', min: 1 }]);

describe('EditPermissions', () => {
    it('names parameters as an assignment does, subsystems joined by $', () => {
        expect(parameterPath([], 'Gain', 'k#Value')).toBe('Gain.k#Value');
        expect(parameterPath(['A', 'Sub'], 'Mass', 'm')).toBe('A$Sub$Mass.m');
        expect(parameterPath([], null, 'gain')).toBe('gain');
        expect(parameterPath(['A', 'Sub'], null, 'gain')).toBe('A$Sub.gain');
    });

    it('a free model allows everything; a locked copy no structural edit', () => {
        for (const edit of ['add', 'delete', 'move', 'rotate', 'flip', 'connect', 'rename', 'group', 'paste'] as const) {
            expect(EditPermissions.free.allows(edit)).toBe(true);
            expect(locked.allows(edit)).toBe(false);
        }
        expect(EditPermissions.free.locked).toBe(false);
        expect(locked.locked).toBe(true);
    });

    it('finds the rule of a listed parameter (an input start value #Value by its parameter), none for others', () => {
        expect(locked.parameterRule([], 'Gain', 'k#Value')).toEqual({ name: 'Gain.k', min: 0, max: 0.1 });
        expect(locked.parameterRule(['Sub'], 'Mass', 'm')).toEqual({ name: 'Sub$Mass.m' });
        expect(locked.parameterRule([], 'Mass', 'm')).toBeNull();
        expect(locked.parameterRule([], 'Other', 'k#Value')).toBeNull();
        expect(locked.parameterRule([], null, 'gain')).toEqual({ name: 'gain', min: 1 });
    });

    it('refuses values outside the bounds, and anything but a plain number where bounds are set', () => {
        expect(locked.valueRefusal([], 'Gain', 'k#Value', '0.05')).toBeNull();
        expect(locked.valueRefusal([], 'Gain', 'k#Value', '0.1')).toBeNull();
        expect(locked.valueRefusal([], 'Gain', 'k#Value', '0.2')).toBe('Gain.k#Value must stay within 0 … 0.1');
        expect(locked.valueRefusal([], 'Gain', 'k#Value', 'gain')).toBe("Gain.k#Value takes a number within 0 … 0.1 here, not 'gain'");
        expect(locked.valueRefusal([], null, 'gain', '0.5')).toBe('gain must stay within ≥ 1');
        expect(locked.valueRefusal(['Sub'], 'Mass', 'm', 'any_expression')).toBeNull();
        expect(locked.valueRefusal([], 'Other', 'x', '1')).toBe('Other.x is not one of the parameters this assignment lets you change');
    });

    it('locks a student\'s own copy of a parameters assignment only', () => {
        const assignment = { edit_mode: 'parameters', parameters: [{ name: 'Gain.k' }] } as Assignment;
        expect(EditPermissions.forAssignment(assignment, true).locked).toBe(true);
        expect(EditPermissions.forAssignment(assignment, false).locked).toBe(false);   // a teacher looking at it
        expect(EditPermissions.forAssignment({ ...assignment, edit_mode: 'free' }, true).locked).toBe(false);
        expect(EditPermissions.forAssignment(null, true).locked).toBe(false);
    });

    it('refuses a locked copy\'s structural edits and out-of-bound values before they reach the server', async () => {
        const server = new FakeServer();
        const free = new EditorStore(structuredClone(server.model), server.handle);
        await free.execute(new AddComponent([], 'SignalGain', 'Gain', at(0, 0)));
        const store = new EditorStore(structuredClone(server.model), permittedTransport(locked, server.handle));
        const sent = server.log.length;

        await expect(store.execute(new MoveComponents([], [{ name: 'Gain', from: at(0, 0), to: at(50, 0) }])))
            .rejects.toMatchObject({ code: 'locked' });
        await expect(store.execute(new AddComponent([], 'SignalStep', 'Step', at(0, 0)))).rejects.toMatchObject({ code: 'locked' });
        await expect(store.execute(new SetParameter([], 'Gain', 'k#Value', '5'))).rejects.toThrow('must stay within 0 … 0.1');
        await expect(store.execute(new SetSystemParameter([], { name: 'other', value: '1', type: 'double', unit: '', description: '' })))
            .rejects.toThrow('not one of the parameters');
        expect(server.log.length).toBe(sent);
        expect(store.history.canUndo).toBe(false);

        await store.execute(new SetParameter([], 'Gain', 'k#Value', '0.05'));
        expect(server.model.system.components[0].parameters.find((p) => p.name === 'k#Value')?.value).toBe('0.05');
    });
});

describe('ParameterPanel of a locked copy', () => {
    const actions: PanelActions = {
        rotate: () => undefined, flip: () => undefined, remove: () => undefined, group: () => undefined, ungroup: () => undefined,
        plotPort: () => undefined, toggleParameterPorts: () => undefined, parameterPortsShown: () => false,
    };

    async function lockedPanel() {
        const server = new FakeServer();
        const setup = new EditorStore(structuredClone(server.model), server.handle);
        await setup.execute(new AddComponent([], 'SignalGain', 'Gain', at(0, 0)));
        await setup.execute(new AddComponent([], 'SignalStep', 'Step', at(100, 0)));
        const permissions = EditPermissions.lockedTo([{ name: 'Gain.k', min: 0, max: 0.1 }]);
        const store = new EditorStore(structuredClone(server.model), permittedTransport(permissions, server.handle));
        const panel = new ParameterPanel(store, actions, permissions);
        document.body.replaceChildren(panel.element);
        return { store, panel };
    }
    const field = (name: string) => document.querySelector<HTMLInputElement>(`input[name="${name}"]`)!;
    const settled = () => new Promise((resolve) => setTimeout(resolve, 0));

    it('takes input in the allowed field only, with its bounds beside it', async () => {
        const { store } = await lockedPanel();
        store.select(['Gain']);
        expect(field('param-k#Value').readOnly).toBe(false);
        expect(document.querySelector('[data-testid="param-bounds"]')?.textContent).toBe('allowed: 0 … 0.1');
        expect(field('component-name').readOnly).toBe(true);
        const buttons = [...document.querySelectorAll<HTMLButtonElement>('.button-row button')];
        for (const label of ['Rotate', 'Flip', 'Delete']) expect(buttons.find((b) => b.textContent === label)?.disabled).toBe(true);

        store.select(['Step']);
        expect(field('param-y_0#Value').readOnly).toBe(true);
        expect(field('param-y_A#Value').readOnly).toBe(true);
        expect(document.querySelector('[data-testid="param-bounds"]')).toBeNull();
        store.select([]);
        expect(document.querySelector('form.sysparam-add')).toBeNull();
    });

    it('puts a refused value back to the last good one and says why', async () => {
        const { store } = await lockedPanel();
        store.select(['Gain']);
        field('param-k#Value').value = '0.05';
        field('param-k#Value').dispatchEvent(new Event('change'));
        await store.idle();
        await settled();
        expect(field('param-k#Value').value).toBe('0.05');

        field('param-k#Value').value = '3';
        field('param-k#Value').dispatchEvent(new Event('change'));
        await store.idle();
        await settled();
        expect(field('param-k#Value').value).toBe('0.05');
        expect(field('param-k#Value').getAttribute('aria-invalid')).toBe('true');
        expect(document.querySelector('.parameter-panel .field-error')?.textContent).toBe('Gain.k#Value must stay within 0 … 0.1');

        // refused again for the same reason: back again
        field('param-k#Value').value = '4';
        field('param-k#Value').dispatchEvent(new Event('change'));
        await store.idle();
        await settled();
        expect(field('param-k#Value').value).toBe('0.05');
    });
});
