// Discrete Fourier transform of logged signals: an in-place radix-2 FFT and the single-sided
// amplitude spectrum of a time range, with a choice of window.

export type WindowName = 'rectangular' | 'hann' | 'hamming' | 'flattop';
export const WINDOWS: readonly WindowName[] = ['hann', 'rectangular', 'hamming', 'flattop'];

/** Window weights for n samples (periodic forms, as used for spectra). */
export function windowWeights(name: WindowName, n: number): Float64Array {
    const w = new Float64Array(n);
    for (let i = 0; i < n; i++) {
        const x = (2 * Math.PI * i) / n;
        switch (name) {
            case 'rectangular': w[i] = 1; break;
            case 'hann': w[i] = 0.5 - 0.5 * Math.cos(x); break;
            case 'hamming': w[i] = 0.54 - 0.46 * Math.cos(x); break;
            case 'flattop':
                w[i] = 0.21557895 - 0.41663158 * Math.cos(x) + 0.277263158 * Math.cos(2 * x)
                    - 0.083578947 * Math.cos(3 * x) + 0.006947368 * Math.cos(4 * x);
                break;
        }
    }
    return w;
}

export function nextPowerOfTwo(n: number): number {
    let p = 1;
    while (p < n) p *= 2;
    return p;
}

/** In-place FFT; the length must be a power of two. */
export function fft(re: Float64Array, im: Float64Array): void {
    const n = re.length;
    if (n !== im.length || (n & (n - 1)) !== 0) throw new Error(`fft: length ${n} is not a power of two`);
    for (let i = 1, j = 0; i < n; i++) {
        let bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) {
            [re[i], re[j]] = [re[j], re[i]];
            [im[i], im[j]] = [im[j], im[i]];
        }
    }
    for (let len = 2; len <= n; len *= 2) {
        const angle = (-2 * Math.PI) / len;
        const wr = Math.cos(angle);
        const wi = Math.sin(angle);
        for (let start = 0; start < n; start += len) {
            let cr = 1;
            let ci = 0;
            for (let k = 0; k < len / 2; k++) {
                const a = start + k;
                const b = a + len / 2;
                const tr = re[b] * cr - im[b] * ci;
                const ti = re[b] * ci + im[b] * cr;
                re[b] = re[a] - tr;
                im[b] = im[a] - ti;
                re[a] += tr;
                im[a] += ti;
                const next = cr * wr - ci * wi;
                ci = cr * wi + ci * wr;
                cr = next;
            }
        }
    }
}

export interface Samples { time: ArrayLike<number>; values: ArrayLike<number> }

/** The samples with from <= t <= to (all of them without a range). */
export function samplesIn(s: Samples, from?: number, to?: number): { time: number[]; values: number[] } {
    const time: number[] = [];
    const values: number[] = [];
    for (let i = 0; i < s.time.length; i++) {
        const t = s.time[i];
        if ((from !== undefined && t < from) || (to !== undefined && t > to)) continue;
        if (!Number.isFinite(s.values[i])) continue;
        time.push(t);
        values.push(s.values[i]);
    }
    return { time, values };
}

export interface Transform { frequency: number[]; re: Float64Array; im: Float64Array; gain: number; sampleRate: number }

/**
 * The windowed transform of evenly spaced samples, zero-padded to a power of two (a finer
 * frequency grid, not more resolution). `gain` is the window's sum, to scale amplitudes.
 */
export function transform(time: number[], values: number[], window: WindowName): Transform {
    const n = values.length;
    if (n < 4) throw new Error('need at least 4 samples in the time range');
    const dt = (time[n - 1] - time[0]) / (n - 1);
    if (!(dt > 0)) throw new Error('the time range has no length');
    const padded = nextPowerOfTwo(n);
    const w = windowWeights(window, n);
    // the mean is removed so that a large offset does not leak over the low frequencies
    const mean = values.reduce((a, b) => a + b, 0) / n;
    const re = new Float64Array(padded);
    const im = new Float64Array(padded);
    let gain = 0;
    for (let i = 0; i < n; i++) {
        re[i] = (values[i] - mean) * w[i];
        gain += w[i];
    }
    fft(re, im);
    const sampleRate = 1 / dt;
    const frequency = Array.from({ length: padded / 2 + 1 }, (_, k) => (k * sampleRate) / padded);
    // bin 0 carries the mean that was taken out
    re[0] = mean * gain;
    im[0] = 0;
    return { frequency, re, im, gain, sampleRate };
}

export interface Spectrum { frequency: number[]; amplitude: number[] }

/** Single-sided amplitude spectrum: a sine of amplitude A shows as A at its frequency. */
export function amplitudeSpectrum(s: Samples, window: WindowName, from?: number, to?: number): Spectrum {
    const picked = samplesIn(s, from, to);
    const t = transform(picked.time, picked.values, window);
    const amplitude = t.frequency.map((_, k) => (Math.hypot(t.re[k], t.im[k]) * (k === 0 ? 1 : 2)) / t.gain);
    return { frequency: t.frequency, amplitude };
}

/** Frequency of the largest amplitude above 0 Hz. */
export function peakFrequency(spectrum: Spectrum): number {
    let best = 1;
    for (let k = 2; k < spectrum.amplitude.length; k++) if (spectrum.amplitude[k] > spectrum.amplitude[best]) best = k;
    return spectrum.frequency[best];
}
