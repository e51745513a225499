// Bode diagram of an output against an input from logged signals: the ratio of their
// transforms, at the frequencies where the input carries energy. Both signals are differenced
// first: the ratio is unchanged (d/dt on both sides), but a step input becomes an impulse,
// whose spectrum covers every frequency instead of leaking from the window's edges.
import { samplesIn, transform, type Samples, type WindowName } from './fft';

export interface Bode { frequency: number[]; gainDb: number[]; phaseDeg: number[] }

/**
 * 'unwrapped' keeps the phase continuous from one frequency to the next, so a lag that grows
 * past -180° reads as such; 'wrapped' gives each phase in (-180°, 180°].
 */
export type PhaseMode = 'unwrapped' | 'wrapped';

export interface BodeOptions {
    window: WindowName;
    from?: number;
    to?: number;
    /** Drops frequencies the input hardly excites (relative to its largest component), where the ratio would be noise. */
    threshold?: number;
    phase?: PhaseMode;
}

export function bode(input: Samples, output: Samples, { window, from, to, threshold = 1e-3, phase = 'unwrapped' }: BodeOptions): Bode {
    const a = samplesIn(input, from, to);
    const b = samplesIn(output, from, to);
    if (a.values.length !== b.values.length) throw new Error('input and output need the same samples');
    const x = transform(a.time.slice(1), differences(a.values), window);
    const y = transform(b.time.slice(1), differences(b.values), window);
    const magnitude = x.frequency.map((_, k) => Math.hypot(x.re[k], x.im[k]));
    const largest = Math.max(...magnitude.slice(1));
    const out: Bode = { frequency: [], gainDb: [], phaseDeg: [] };
    let previous = 0;
    for (let k = 1; k < x.frequency.length; k++) {
        if (!(magnitude[k] > threshold * largest)) continue;
        // H = Y / X
        const d = x.re[k] * x.re[k] + x.im[k] * x.im[k];
        const hr = (y.re[k] * x.re[k] + y.im[k] * x.im[k]) / d;
        const hi = (y.im[k] * x.re[k] - y.re[k] * x.im[k]) / d;
        let degrees = (Math.atan2(hi, hr) * 180) / Math.PI;
        if (phase === 'unwrapped') {
            while (degrees - previous > 180) degrees -= 360;
            while (degrees - previous < -180) degrees += 360;
            previous = degrees;
        } else if (degrees <= -180) {
            degrees += 360;   // atan2 gives -180° for a negative real ratio with a -0 imaginary part
        }
        out.frequency.push(x.frequency[k]);
        out.gainDb.push(20 * Math.log10(Math.hypot(hr, hi)));
        out.phaseDeg.push(degrees);
    }
    return out;
}

function differences(values: number[]): number[] {
    return values.slice(1).map((v, i) => v - values[i]);
}
