import { defineConfig } from 'vitest/config';

// Dev server proxies the API and its WebSocket (/api/v1/ws) to a locally running tlmhub-server.
const server = process.env.TLMHUB_DEV_SERVER ?? 'http://127.0.0.1:8080';
// With TLMHUB_TEST_REPORT_DIR (scripts/test.sh) Vitest also writes a JUnit file there, from
// which the script checks that every listed test ran.
const reportDir = process.env.TLMHUB_TEST_REPORT_DIR;

export default defineConfig({
    build: { outDir: 'dist', emptyOutDir: true, sourcemap: true, chunkSizeWarningLimit: 800 },
    server: {
        proxy: {
            '/api': { target: server, ws: true },
        },
    },
    test: {
        include: ['src/**/*.test.ts', 'scripts/**/*.test.ts'],
        environment: 'node',
        // One module graph and environment per worker instead of per file: 70 CPU-s -> 21 CPU-s
        // for the suite here, the most of it jsdom set-ups. Tests restore what they stub.
        isolate: false,
        reporters: reportDir ? ['default', 'junit'] : ['default'],
        outputFile: reportDir ? { junit: `${reportDir}/vitest-unit.xml` } : undefined,
    },
});
