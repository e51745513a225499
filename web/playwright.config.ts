import { defineConfig } from '@playwright/test';

// The suite drives Debian's Chromium (no browser download) against a real tlmhub-server
// that e2e/globalSetup.ts starts on a free port with a fresh data directory.
// With TLMHUB_TEST_REPORT_DIR (scripts/test.sh) it also writes a JUnit file there, from which
// the script checks that every listed test ran.
const reportDir = process.env.TLMHUB_TEST_REPORT_DIR;

export default defineConfig({
    testDir: 'e2e',
    timeout: 90_000,
    expect: { timeout: 15_000 },
    workers: 1,
    fullyParallel: false,
    retries: 0,
    reporter: reportDir ? [['list'], ['junit', { outputFile: `${reportDir}/playwright-e2e.xml` }]] : [['list']],
    globalSetup: './e2e/globalSetup.ts',
    use: {
        viewport: { width: 1440, height: 900 },
        screenshot: 'only-on-failure',
        trace: 'off',
        launchOptions: {
            executablePath: process.env.TLMHUB_CHROMIUM ?? '/usr/bin/chromium',
            args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
                '--disable-background-networking', '--disable-component-update', '--disable-sync'],
        },
    },
});
