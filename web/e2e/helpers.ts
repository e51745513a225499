// Shared steps of the browser tests.
import { expect, type Page, type APIRequestContext } from '@playwright/test';
import { USERS } from './globalSetup';

export function baseUrl(): string {
    const url = process.env.TLMHUB_E2E_URL;
    if (!url) throw new Error('TLMHUB_E2E_URL not set (globalSetup did not run)');
    return url;
}

export async function login(page: Page, user: keyof typeof USERS): Promise<void> {
    await loginWith(page, user, USERS[user]);
}

/** Logs in through the login page as any account (one a test made), to the model list. */
export async function loginWith(page: Page, username: string, password: string): Promise<void> {
    await page.goto(`${baseUrl()}/#/login`);
    await page.getByLabel('User name').fill(username);
    await page.getByLabel('Password').fill(password);
    await page.getByRole('button', { name: 'Log in' }).click();
    await expect(page.getByRole('heading', { name: 'Examples' })).toBeVisible();
}

/** Token of the logged-in tab, for REST checks next to the UI. */
export async function tokenOf(page: Page): Promise<string> {
    const token = await page.evaluate(() => sessionStorage.getItem('tlmhub.token'));
    if (!token) throw new Error('not logged in');
    return token;
}

export async function api<T>(request: APIRequestContext, page: Page, path: string): Promise<T> {
    const response = await request.get(`${baseUrl()}/api/v1${path}`, { headers: { Authorization: `Bearer ${await tokenOf(page)}` } });
    expect(response.status(), `GET ${path}`).toBe(200);
    return response.json() as Promise<T>;
}

export async function openExample(page: Page, name: string): Promise<number> {
    const row = page.getByTestId('example-models').locator('tr', { has: page.getByRole('link', { name, exact: true }) });
    await row.getByRole('button', { name: 'Open' }).click();
    await expect(page.getByTestId('model-name')).toHaveText(name);
    await expect(page.locator('.canvas .component').first()).toBeVisible();
    return Number(/#\/model\/(\d+)/.exec(page.url())![1]);
}

export function port(page: Page, component: string, portName: string) {
    return page.locator(`.canvas [data-component="${component}"][data-port="${portName}"]`);
}

/** Drags with the mouse from one port to another, in small steps as a person would. */
export async function dragPortToPort(page: Page, from: [string, string], to: [string, string]): Promise<void> {
    const a = await port(page, ...from).boundingBox();
    const b = await port(page, ...to).boundingBox();
    if (!a || !b) throw new Error(`port not visible: ${from.join('.')} or ${to.join('.')}`);
    await page.mouse.move(a.x + a.width / 2, a.y + a.height / 2);
    await page.mouse.down();
    await page.mouse.move((a.x + b.x) / 2, (a.y + b.y) / 2, { steps: 5 });
    await page.mouse.move(b.x + b.width / 2, b.y + b.height / 2, { steps: 5 });
    await page.mouse.up();
}

/** Clicks a port and picks one of its variables for the active plot window. */
export async function plotVariable(page: Page, component: string, portName: string, variable: string): Promise<string> {
    await port(page, component, portName).click();
    const item = page.locator('.variable-picker [role="menuitem"]', { hasText: variable }).first();
    await expect(item).toBeVisible();
    const name = (await item.getAttribute('data-variable'))!;
    await item.click();
    return name;
}

export async function setRunField(page: Page, label: string, value: string): Promise<void> {
    await page.getByLabel(label, { exact: true }).fill(value);
}

export async function runAndWait(page: Page): Promise<number> {
    const status = page.getByTestId('run-status');
    // The status still shows the previous run (done) until the server accepts the new one.
    const previousJob = await status.getAttribute('data-job');
    await page.getByTestId('run').click();
    if (previousJob) await expect(status).not.toHaveAttribute('data-job', previousJob, { timeout: 60_000 });
    await expect(status).toHaveAttribute('data-state', 'done', { timeout: 60_000 });
    return Number(await status.getAttribute('data-job'));
}

/** The plotted data of a variable in the first plot window (current run, or the previous). */
export async function plotted(page: Page, name: string, previous = false): Promise<number[]> {
    return page.evaluate(([n, p]) => {
        const app = (window as unknown as { __tlmhub: { plots: { windows: { seriesData(n: string, p: boolean): number[] }[] } } }).__tlmhub;
        return [...app.plots.windows[0].seriesData(n as string, p as boolean)];
    }, [name, previous] as const);
}

/** Sets Position Servo's proportional gain (GainP's input k) in the parameter panel. */
export async function setServoGain(page: Page, value: string): Promise<void> {
    await page.locator('.canvas .component[data-name="GainP"] .icon-frame').click();
    const gain = page.getByLabel('k#Value value');
    await gain.fill(value);
    await gain.press('Enter');
    await expect(page.locator('.parameter-panel .field-error')).toHaveCount(0);
}
