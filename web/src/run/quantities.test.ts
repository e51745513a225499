import { describe, expect, it } from 'vitest';
import { quantityOf } from './quantities';

// (the base unit comes from the node type of the port the variable was picked on)
describe('quantities', () => {
    it('follow from the base unit where only one quantity has it', () => {
        expect(quantityOf('Pressure_Source#P1#Pressure', 'Pa')).toBe('Pressure');
        expect(quantityOf('Cylinder_C#P1#Flow', 'm^3/s')).toBe('Flow');
        expect(quantityOf('Mass#P2#Position', 'm')).toBe('Position');
        expect(quantityOf('Volume#P1#Temperature', 'K')).toBe('Temperature');
        expect(quantityOf('Motor#P1#Torque', 'Nm')).toBe('Torque');
        // a wave variable of a hydraulic node is a pressure
        expect(quantityOf('Volume#P1#WaveVariable', 'Pa')).toBe('Pressure');
        // EnergyFlow is logged in J/s: Hopsan's Power
        expect(quantityOf('Source#P1#EnergyFlow', 'J/s')).toBe('Power');
    });

    it('the variable\'s name decides between quantities of one base unit (rad/s)', () => {
        expect(quantityOf('Inertia#P1#AngularVelocity', 'rad/s')).toBe('AngularVelocity');
        expect(quantityOf('Sensor#out#Frequency', 'rad/s')).toBe('Frequency');
        expect(quantityOf('Gain#out#Value', 'rad/s')).toBeNull();
    });

    it('none for signals and units Hopsan has no quantity of', () => {
        expect(quantityOf('Gain#out#Value', '')).toBeNull();
        expect(quantityOf('Volume#P1#CharImpedance', 'Pa s/m^3')).toBeNull();
    });
});
