// Hopsan's default display units per physical quantity (its unitsettings configuration, as
// recorded in the project's reference). Facts only: a value in the base unit is
// scale * (value in the display unit) + offset; only temperatures have an offset.
export interface UnitScale { name: string; scale: number; offset?: number }

export interface QuantityUnits { quantity: string; base: string; units: UnitScale[] }

export const UNIT_SCALES: readonly QuantityUnits[] = [
    { quantity: 'Position', base: 'm', units: [
        { name: 'mm', scale: 0.001 },
        { name: 'cm', scale: 0.01 },
        { name: 'dm', scale: 0.1 },
        { name: 'km', scale: 1000 },
        { name: 'ft', scale: 0.30480370641307 },
        { name: 'inch', scale: 0.025400050800101603 },
    ] },
    { quantity: 'Velocity', base: 'm/s', units: [
        { name: 'km/h', scale: 0.2777777777777778 },
        { name: 'mph', scale: 0.44704 },
        { name: 'knot', scale: 0.5144444444444445 },
    ] },
    { quantity: 'Voltage', base: 'V', units: [] },
    { quantity: 'Current', base: 'A', units: [] },
    { quantity: 'Time', base: 's', units: [
        { name: 'ms', scale: 0.001 },
        { name: 'us', scale: 0.000001 },
        { name: 'ns', scale: 1e-9 },
        { name: 'min', scale: 60 },
    ] },
    { quantity: 'Frequency', base: 'rad/s', units: [
        { name: 'Hz', scale: 6.283185307179586 },
        { name: 'kHz', scale: 6283.185307179586 },
        { name: 'MHz', scale: 6283185.307179586 },
        { name: 'GHz', scale: 6283185307.179586 },
    ] },
    { quantity: 'Angle', base: 'rad', units: [
        { name: 'deg', scale: 0.017453292519943295 },
    ] },
    { quantity: 'AngularVelocity', base: 'rad/s', units: [
        { name: 'deg/s', scale: 0.017453292519943295 },
        { name: 'rev/s', scale: 6.283185307179586 },
        { name: 'rpm', scale: 0.10471975511965977 },
    ] },
    { quantity: 'Flow', base: 'm^3/s', units: [
        { name: 'l/min', scale: 0.000016666666666666667 },
    ] },
    { quantity: 'Force', base: 'N', units: [
        { name: 'kN', scale: 1000 },
    ] },
    { quantity: 'Torque', base: 'Nm', units: [] },
    { quantity: 'Pressure', base: 'Pa', units: [
        { name: 'bar', scale: 100000 },
        { name: 'MPa', scale: 1000000 },
        { name: 'psi', scale: 6894.76 },
        { name: 'kPa', scale: 1000 },
        { name: 'GPa', scale: 1000000000 },
    ] },
    { quantity: 'Area', base: 'm^2', units: [
        { name: 'mm^2', scale: 0.000001 },
        { name: 'cm^2', scale: 0.0001 },
        { name: 'dm^2', scale: 0.01 },
        { name: 'ft^2', scale: 0.09290529944314495 },
        { name: 'inch^2', scale: 0.000645162580647742 },
    ] },
    { quantity: 'Volume', base: 'm^3', units: [
        { name: 'cm^3', scale: 0.000001 },
        { name: 'l', scale: 0.001 },
    ] },
    { quantity: 'Displacement', base: 'm^3/rev', units: [
        { name: 'cm^3/rev', scale: 0.000001 },
    ] },
    { quantity: 'Temperature', base: 'K', units: [
        { name: 'C', scale: 1, offset: 273.15 },
        { name: 'F', scale: 0.5555555555555556, offset: 255.3722222222222 },
    ] },
    { quantity: 'Density', base: 'kg/m^3', units: [] },
    { quantity: 'Momentum', base: 'kg m/s', units: [] },
    { quantity: 'Energy', base: 'J', units: [
        { name: 'mJ', scale: 0.001 },
        { name: 'kJ', scale: 1000 },
        { name: 'MJ', scale: 1000000 },
    ] },
    { quantity: 'Power', base: 'J/s', units: [
        { name: 'mW', scale: 0.001 },
        { name: 'W', scale: 1 },
        { name: 'kW', scale: 1000 },
        { name: 'MW', scale: 1000000 },
    ] },
    { quantity: 'Mass', base: 'kg', units: [
        { name: 'g', scale: 0.001 },
        { name: 'hg', scale: 0.01 },
        { name: 't', scale: 1000 },
    ] },
    { quantity: 'Resistance', base: 'ohm', units: [
        { name: 'milliohm', scale: 0.001 },
        { name: 'kilohm', scale: 1000 },
        { name: 'megohm', scale: 1000000 },
    ] },
    { quantity: 'Magnitude', base: '-', units: [
        { name: 'dB', scale: 1 },
    ] },
    { quantity: 'LeakageCoefficient', base: '(m^3/s)/Pa', units: [
        { name: 'm^5/(Ns)', scale: 1 },
        { name: '(l/min)/bar', scale: 1 },
    ] },
];
