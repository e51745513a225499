// A live session in a lab (issue 42 item 6): a teacher goes live on Position Servo and shares
// the session with her class; a student of the class sees it on the class page, watches it
// read-only, and its frames arrive (the model time goes on in the watch page, the plot fills).
import { copyFileSync, mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { test, expect, type APIRequestContext, type Browser, type Page } from './fixtures';
import { baseUrl, loginWith, openExample, setRunField } from './helpers';
import { ADMIN_PASSWORD } from './globalSetup';

const TEACHER = 'lena';
const STUDENT = 'leo';
const password = (user: string) => `${user}-live-lab-password`;
const screenshots = fileURLToPath(new URL('./screenshots/', import.meta.url));
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));

async function authorised(request: APIRequestContext, username: string, pass: string): Promise<Record<string, string>> {
    const login = await request.post(`${baseUrl()}/api/v1/auth/login`, { data: { username, password: pass } });
    expect(login.ok()).toBe(true);
    return { Authorization: `Bearer ${(await login.json() as { token: string }).token}` };
}

/** The teacher and the student, and the teacher's class with the student in it; its id. */
async function classWithStudent(request: APIRequestContext): Promise<number> {
    const admin = await authorised(request, 'admin', ADMIN_PASSWORD);
    for (const [username, role] of [[TEACHER, 'teacher'], [STUDENT, 'user']]) {
        const created = await request.post(`${baseUrl()}/api/v1/users`, { headers: admin, data: { username, password: password(username), role } });
        expect(created.status(), `creating ${username}`).toBe(201);
    }
    const created = await request.post(`${baseUrl()}/api/v1/classes`, {
        headers: await authorised(request, TEACHER, password(TEACHER)), data: { name: 'Live lab' },
    });
    expect(created.status()).toBe(201);
    const theClass = await created.json() as { id: number; join_code: string };
    const joined = await request.post(`${baseUrl()}/api/v1/classes/join`, {
        headers: await authorised(request, STUDENT, password(STUDENT)), data: { code: theClass.join_code },
    });
    expect(joined.status()).toBe(200);
    return theClass.id;
}

async function loggedIn(browser: Browser, username: string): Promise<Page> {
    const page = await (await browser.newContext()).newPage();
    await loginWith(page, username, password(username));
    return page;
}

/** The model time the watch page shows ("Live · t = 1.23 s"). */
async function watchedTime(page: Page): Promise<number> {
    const text = await page.getByTestId('watch-status').textContent() ?? '';
    const time = /t = ([-\d.e]+) s/.exec(text);
    return time ? Number(time[1]) : Number.NaN;
}

test('a teacher shares her live session with the class; a student watches it read-only as its frames arrive', async ({ browser, request }) => {
    const classId = await classWithStudent(request);

    // the teacher: Position Servo with a stop time long enough to watch, saved as hers, live
    const teacher = await loggedIn(browser, TEACHER);
    await openExample(teacher, 'Position Servo');
    await setRunField(teacher, 'Stop time', '120');
    await teacher.getByLabel('Stop time', { exact: true }).press('Enter');
    await teacher.getByTestId('save').click();
    await expect(teacher.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
    await teacher.getByTestId('live').click();
    await expect(teacher.getByTestId('live-status')).toContainText('Live');
    await teacher.getByTestId('live-share').click();
    const dialog = teacher.getByTestId('live-share-dialog');
    await dialog.getByLabel('Class').selectOption({ label: 'Live lab' });
    await dialog.getByTestId('live-share-ok').click();
    await expect(teacher.locator('.toast', { hasText: 'Shared with Live lab' })).toBeVisible();

    // the student: the class page says the teacher is live; Watch opens the session read-only
    const student = await loggedIn(browser, STUDENT);
    await student.goto(`${baseUrl()}/#/class/${classId}`);
    const watch = student.getByTestId('live-now').getByTestId('watch-live');
    await expect(watch).toBeVisible();
    await expect(student.getByTestId('live-now')).toContainText(`${TEACHER} is live with Position Servo`);
    await watch.click();
    await expect(student.getByTestId('watch-page')).toBeVisible();
    await expect(student.getByTestId('watch-model-name')).toHaveText('Position Servo');
    await expect(student.locator('.canvas .component[data-name="GainP"]')).toBeVisible();
    // frames arrive: the model time goes on
    await expect(student.getByTestId('watch-status')).toContainText('Live');
    const first = await watchedTime(student);
    await expect.poll(() => watchedTime(student), { timeout: 10_000 }).toBeGreaterThan(first + 0.5);
    // nothing on the page controls the session
    await expect(student.getByTestId('live-pause')).toHaveCount(0);
    await expect(student.getByTestId('live-control-input')).toHaveCount(0);
    mkdirSync(screenshots, { recursive: true });
    mkdirSync(docsScreenshots, { recursive: true });
    await student.screenshot({ path: `${screenshots}live-lab-watch.png` });
    copyFileSync(`${screenshots}live-lab-watch.png`, `${docsScreenshots}live-lab-watch.png`);

    // the teacher stops: the student's page says it ended
    await teacher.getByTestId('live-stop').click();
    await expect(student.getByTestId('watch-status')).toContainText('Ended');
});
