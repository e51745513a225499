import { describe, expect, it } from 'vitest';
import { amplitudeSpectrum, fft, peakFrequency, WINDOWS } from './fft';
import { bode } from './bode';

const sampled = (n: number, dt: number, f: (t: number) => number) => {
    const time = Array.from({ length: n }, (_, i) => i * dt);
    return { time, values: time.map(f) };
};

describe('fft', () => {
    it('matches a direct DFT (tolerance 1e-9)', () => {
        const n = 16;
        const x = Array.from({ length: n }, (_, i) => Math.sin(i * 0.7) + 0.3 * Math.cos(i * 2.1) + (i % 3));
        const re = Float64Array.from(x);
        const im = new Float64Array(n);
        fft(re, im);
        for (let k = 0; k < n; k++) {
            let sr = 0;
            let si = 0;
            for (let i = 0; i < n; i++) {
                sr += x[i] * Math.cos((-2 * Math.PI * k * i) / n);
                si += x[i] * Math.sin((-2 * Math.PI * k * i) / n);
            }
            expect(re[k]).toBeCloseTo(sr, 9);
            expect(im[k]).toBeCloseTo(si, 9);
        }
    });
});

describe('amplitudeSpectrum', () => {
    // 10 s at 1 kHz, as a default run logs it
    const sine = sampled(10001, 1e-3, (t) => 2.5 * Math.sin(2 * Math.PI * 7.3 * t) + 1);

    it.each(WINDOWS)('a 7.3 Hz sine peaks within one frequency bin of 7.3 Hz (%s window)', (window) => {
        const s = amplitudeSpectrum(sine, window);
        const bin = s.frequency[1] - s.frequency[0];
        expect(Math.abs(peakFrequency(s) - 7.3)).toBeLessThanOrEqual(bin);
    });

    it('shows the amplitude of a sine that fits the range in whole periods (flat-top window, 1 %)', () => {
        const s = amplitudeSpectrum(sine, 'flattop');
        expect(Math.max(...s.amplitude.slice(1))).toBeGreaterThan(2.5 * 0.99);
        expect(Math.max(...s.amplitude.slice(1))).toBeLessThan(2.5 * 1.01);
        expect(s.amplitude[0]).toBeCloseTo(1, 2);
    });

    it('uses only the chosen time range', () => {
        const switching = sampled(10001, 1e-3, (t) => (t < 5 ? Math.sin(2 * Math.PI * 3 * t) : Math.sin(2 * Math.PI * 40 * t)));
        const late = amplitudeSpectrum(switching, 'hann', 5, 10);
        expect(Math.abs(peakFrequency(late) - 40)).toBeLessThanOrEqual(late.frequency[1]);
    });
});

describe('bode', () => {
    it("a first-order filter's gain is -3 dB and its phase -45° at its corner frequency (0.2 dB, 2°)", () => {
        // input: sines at many frequencies; output: the filter's exact steady-state answer
        const corner = 12.5;
        const n = 8192;
        const dt = 1 / 1024;
        const frequencies = Array.from({ length: 40 }, (_, i) => (i + 1) * 2.5);
        const input = sampled(n, dt, (t) => frequencies.reduce((sum, f) => sum + Math.sin(2 * Math.PI * f * t), 0));
        const output = sampled(n, dt, (t) => frequencies.reduce((sum, f) => {
            const ratio = f / corner;
            return sum + Math.sin(2 * Math.PI * f * t - Math.atan(ratio)) / Math.sqrt(1 + ratio * ratio);
        }, 0));
        const b = bode(input, output, { window: 'hann' });
        const at = b.frequency.reduce((best, f, i) => (Math.abs(f - corner) < Math.abs(b.frequency[best] - corner) ? i : best), 0);
        expect(b.frequency[at]).toBeCloseTo(corner, 6);
        expect(Math.abs(b.gainDb[at] - -3.0103)).toBeLessThan(0.2);
        expect(Math.abs(b.phaseDeg[at] - -45)).toBeLessThan(2);
        // and far above the corner the gain falls by 20 dB per decade
        const high = b.frequency.findIndex((f) => Math.abs(f - 100) < 1e-9);
        expect(Math.abs(b.gainDb[high] - 20 * Math.log10(1 / Math.sqrt(1 + 64)))).toBeLessThan(0.2);
    });

    // The step response of a third-order lag 1 / (1 + s/ωc)³, as a run logs it: the phase
    // -3·atan(f/fc) passes -180° at fc·√3 and tends to -270°, so above fc·√3 the wrapped and the
    // unwrapped phase differ by 360°. (Sampling every 0.1 ms shifts the phase by half a
    // sample, under 0.8° up to 40 Hz.)
    describe('the step response of a third-order lag (0.3 dB, 2°)', () => {
        const corner = 5;
        const w = 2 * Math.PI * corner;
        const stepAt = 0.1;
        const input = sampled(32768, 1e-4, (t) => (t >= stepAt - 1e-9 ? 1 : 0));
        const output = sampled(32768, 1e-4, (t) => {
            const x = Math.max(0, w * (t - stepAt));
            return 1 - Math.exp(-x) * (1 + x + (x * x) / 2);
        });
        const lagDeg = (f: number) => (-3 * Math.atan(f / corner) * 180) / Math.PI;
        const gainDb = (f: number) => -30 * Math.log10(1 + (f / corner) ** 2);   // 20·log10((1 + (f/fc)²)^-3/2)
        const upTo40 = (b: { frequency: number[] }) => b.frequency.map((f, i) => [f, i]).filter(([f]) => f <= 40);

        it('unwrapped, the phase follows -3·atan(f/fc) below -180°', () => {
            const b = bode(input, output, { window: 'rectangular', phase: 'unwrapped' });
            for (const [f, i] of upTo40(b)) {
                expect(Math.abs(b.gainDb[i] - gainDb(f))).toBeLessThan(0.3);
                expect(Math.abs(b.phaseDeg[i] - lagDeg(f))).toBeLessThan(2);
            }
            expect(Math.min(...upTo40(b).map(([, i]) => b.phaseDeg[i]))).toBeLessThan(-240);   // -248.6° at 40 Hz
        });

        it('wrapped, every phase is in (-180°, 180°] and the lag modulo 360°', () => {
            const b = bode(input, output, { window: 'rectangular', phase: 'wrapped' });
            for (const p of b.phaseDeg) {
                expect(p).toBeGreaterThan(-180);
                expect(p).toBeLessThanOrEqual(180);
            }
            const wrapped = (deg: number) => (deg <= -180 ? deg + 360 : deg);
            // away from -180° itself, where 2° of error may land on either side of the cut
            for (const [f, i] of upTo40(b).filter(([f]) => Math.abs(lagDeg(f) + 180) > 2)) {
                expect(Math.abs(b.phaseDeg[i] - wrapped(lagDeg(f)))).toBeLessThan(2);
            }
        });
    });
});
