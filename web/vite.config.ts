import { defineConfig } from 'vitest/config';

// Dev server proxies the API and its WebSocket (/api/v1/ws) to a locally running tlmhub-server.
const server = process.env.TLMHUB_DEV_SERVER ?? 'http://127.0.0.1:8080';

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
    },
});
