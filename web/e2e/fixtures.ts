// The specs' `test`: every page a test opens, in its own context or in one the test makes,
// is watched for Content Security Policy violations (Chromium logs each as a console error),
// and a test that caused any fails, naming them. The server's policy is in
// server/http/SecurityHeaders.cpp; what the app needs beyond 'self' is listed in SECURITY.md.
import { test as base, expect, type BrowserContext, type Page } from '@playwright/test';

export type { APIRequestContext, Browser, Page, WebSocketRoute } from '@playwright/test';
export { expect };

export const test = base.extend<{ contentSecurityPolicyViolations: string[] }>({
    contentSecurityPolicyViolations: [async ({ context, browser }, use) => {
        const violations: string[] = [];
        const watchPage = (page: Page) => page.on('console', (message) => {
            if (message.type() === 'error' && message.text().includes('Content Security Policy')) {
                violations.push(`${page.url()}: ${message.text()}`);
            }
        });
        const watchContext = (watched: BrowserContext) => {
            watched.pages().forEach(watchPage);
            watched.on('page', watchPage);
        };
        watchContext(context);
        const newContext = browser.newContext.bind(browser);
        browser.newContext = async (options) => {
            const made = await newContext(options);
            watchContext(made);
            return made;
        };
        try {
            await use(violations);
        } finally {
            browser.newContext = newContext;
        }
        expect(violations, 'Content Security Policy violations').toEqual([]);
    }, { auto: true }],
});
