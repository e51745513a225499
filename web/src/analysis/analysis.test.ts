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
        const b = bode(input, output, 'hann');
        const at = b.frequency.reduce((best, f, i) => (Math.abs(f - corner) < Math.abs(b.frequency[best] - corner) ? i : best), 0);
        expect(b.frequency[at]).toBeCloseTo(corner, 6);
        expect(Math.abs(b.gainDb[at] - -3.0103)).toBeLessThan(0.2);
        expect(Math.abs(b.phaseDeg[at] - -45)).toBeLessThan(2);
        // and far above the corner the gain falls by 20 dB per decade
        const high = b.frequency.findIndex((f) => Math.abs(f - 100) < 1e-9);
        expect(Math.abs(b.gainDb[high] - 20 * Math.log10(1 / Math.sqrt(1 + 64)))).toBeLessThan(0.2);
    });
});
