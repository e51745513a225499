// @vitest-environment jsdom
import { describe, expect, it, vi } from 'vitest';
import { AxisChoice } from './axisChoice';

const plot = (id: number) => ({ id, axisUnits: () => ['Pa', 'm', 'm^3/s', 'N'] });

function buttonNamed(choice: AxisChoice<ReturnType<typeof plot>>, text: string): HTMLButtonElement {
    return [...choice.element.querySelectorAll('button')].find((b) => b.textContent === text)!;
}

describe('AxisChoice', () => {
    it('names the variable and the window\'s axes, and adds the axis when asked to', () => {
        const addAxis = vi.fn();
        const newWindow = vi.fn();
        const choice = new AxisChoice<ReturnType<typeof plot>>({ addAxis, newWindow });
        expect(choice.element.hidden).toBe(true);
        const target = plot(1);
        choice.ask(target, { name: 'Mass#P2#Velocity', label: 'Mass.P2 Velocity', unit: 'm/s' });
        expect(choice.element.hidden).toBe(false);
        expect(choice.element.textContent).toContain('Mass.P2 Velocity [m/s]: Plot 1 has 4 axes already (Pa, m, m^3/s, N).');
        buttonNamed(choice, 'Add an axis to Plot 1').click();
        expect(addAxis).toHaveBeenCalledWith(target, [{ name: 'Mass#P2#Velocity', label: 'Mass.P2 Velocity', unit: 'm/s' }]);
        expect(newWindow).not.toHaveBeenCalled();
        expect(choice.element.hidden).toBe(true);
        expect(choice.asking).toBeNull();
    });

    it('gathers the variables asked for one window, once each, and opens them in a new window', () => {
        const newWindow = vi.fn();
        const choice = new AxisChoice<ReturnType<typeof plot>>({ addAxis: vi.fn(), newWindow });
        const target = plot(2);
        choice.ask(target, { name: 'a#p#Value', unit: '' });
        choice.ask(target, { name: 'b#p#Value', unit: '' });
        choice.ask(target, { name: 'a#p#Value', unit: '' });
        expect(choice.element.textContent).toContain('a#p#Value [no unit] and 1 more: Plot 2');
        buttonNamed(choice, 'Open a new plot window').click();
        expect(newWindow).toHaveBeenCalledWith([{ name: 'a#p#Value', unit: '' }, { name: 'b#p#Value', unit: '' }]);
    });

    it('a question about another window replaces the last one; Cancel adds nothing', () => {
        const addAxis = vi.fn();
        const choice = new AxisChoice<ReturnType<typeof plot>>({ addAxis, newWindow: vi.fn() });
        choice.ask(plot(1), { name: 'a#p#Value', unit: '' });
        const other = plot(3);
        choice.ask(other, { name: 'b#p#Value', unit: '' });
        expect(choice.asking).toBe(other);
        expect(choice.element.textContent).toContain('b#p#Value [no unit]: Plot 3');
        buttonNamed(choice, 'Cancel').click();
        expect(choice.element.hidden).toBe(true);
        expect(addAxis).not.toHaveBeenCalled();
    });
});
