// A whole teaching lab through the UI (docs/labs.md): the teacher makes a solution from the
// Position Servo example, creates a class and an assignment (students may change GainP.k
// only) with a pretest curve check and a scalar check; two students join with the code,
// tune GainP.k in their copies, run, pretest and hand in; the teacher sees both on the
// dashboard and in the overlay plot, comments on a hand-in (the student reads it) and exports
// the gradebook.
import { test, expect, type Browser, type Page, type APIRequestContext } from './fixtures';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { baseUrl, loginWith, runAndWait } from './helpers';
import { ADMIN_PASSWORD } from './globalSetup';

const TEACHER = 'tina';
const STUDENTS = [
    { name: 'stan', k: '0.02' },     // the solution's value: the curve check passes
    { name: 'stella', k: '0.01' },
];
const VARIABLE = 'Mass#P2#Position';
const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));
const password = (user: string) => `${user}-lab-password`;

async function createAccounts(request: APIRequestContext): Promise<void> {
    const login = await request.post(`${baseUrl()}/api/v1/auth/login`, { data: { username: 'admin', password: ADMIN_PASSWORD } });
    expect(login.ok()).toBe(true);
    const { token } = await login.json() as { token: string };
    for (const [username, role] of [[TEACHER, 'teacher'], ...STUDENTS.map((s) => [s.name, 'user'])]) {
        const created = await request.post(`${baseUrl()}/api/v1/users`, {
            headers: { Authorization: `Bearer ${token}` }, data: { username, password: password(username), role },
        });
        expect(created.status(), `creating ${username}`).toBe(201);
    }
}

async function loggedIn(browser: Browser, username: string): Promise<Page> {
    const context = await browser.newContext({ acceptDownloads: true });
    const page = await context.newPage();
    await loginWith(page, username, password(username));
    return page;
}

/** In the open editor: sets GainP's gain. */
async function setGain(page: Page, k: string): Promise<void> {
    await page.locator('.canvas .component[data-name="GainP"] .icon-frame').click();
    const gain = page.getByLabel('k#Value value');
    await gain.fill(k);
    await gain.press('Enter');
    await expect(page.locator('.parameter-panel .field-error')).toHaveCount(0);
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'true');
}

test('a whole lab: class, assignment, checks, two students hand in, dashboard, overlay, comment, gradebook', async ({ browser, request }) => {
    test.setTimeout(120_000);
    await createAccounts(request);

    // ---- the teacher: a solution model (the example with GainP.k = 0.02), a class, an assignment
    const teacher = await loggedIn(browser, TEACHER);
    const example = teacher.getByTestId('example-models').locator('tr', { has: teacher.getByRole('link', { name: 'Position Servo', exact: true }) });
    await example.getByRole('button', { name: 'Open' }).click();
    await expect(teacher.getByTestId('model-name')).toHaveText('Position Servo');
    const exampleUrl = teacher.url();
    await setGain(teacher, STUDENTS[0].k);
    await teacher.getByTestId('save').click();   // "Save as my copy"
    await expect(teacher.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
    await expect.poll(() => teacher.url()).not.toBe(exampleUrl);

    await teacher.getByTestId('nav-classes').click();
    await teacher.getByLabel('Class name').fill('Fluid power lab');
    await teacher.getByRole('button', { name: 'Create class' }).click();
    await expect(teacher.getByTestId('class-name')).toHaveText('Fluid power lab');
    const joinCode = (await teacher.getByTestId('join-code').textContent())!.trim();
    expect(joinCode).toMatch(/^[A-Za-z0-9]{12}$/);
    const classUrl = teacher.url();

    await teacher.getByTestId('new-assignment').click();
    const form = teacher.getByRole('form', { name: 'New assignment' });
    await form.getByLabel('Title').fill('Tune the servo');
    await form.getByLabel('Instructions (Markdown)').fill([
        '# Task',
        '',
        'Set the **proportional gain** `GainP.k` so that the mass follows the step *without* a large overshoot.',
        '',
        '1. Open your copy and change `GainP.k` (between 0 and 0.1).',
        '2. Save, run, and run the pretests.',
        '3. Hand in.',
        '',
        'Background: [Hopsan](https://github.com/Hopsan/hopsan).',
    ].join('\n'));
    await form.getByLabel('Template model').selectOption({ label: 'Position Servo (example)' });
    await form.getByLabel('Solution model').selectOption({ label: 'Position Servo' });
    await expect(form.getByLabel('Students may change')).toHaveValue('parameters');
    await form.getByRole('button', { name: 'Add parameter' }).click();
    await form.getByLabel('Parameter 1 name').fill('GainP.k');
    await form.getByLabel('Parameter 1 min').fill('0');
    await form.getByLabel('Parameter 1 max').fill('0.1');
    await form.getByRole('button', { name: 'Create assignment' }).click();
    await expect(teacher.getByTestId('assignment-title')).toHaveText('Tune the servo');
    await expect(teacher.locator('.assignment-meta')).toContainText('GainP.k (0 … 0.1)');
    const assignmentUrl = teacher.url();

    // the checks: a pretest curve check and a scalar check at hand-in
    const checks = teacher.getByRole('form', { name: 'Checks' });
    await checks.getByTestId('add-check').click();
    await checks.getByTestId('add-check').click();
    const curve = checks.getByRole('group', { name: 'Check 1' });
    await curve.getByLabel('Check name').fill('Position follows the reference');
    await curve.getByLabel('Points').fill('2');
    await curve.getByLabel('Pretest').check();
    await curve.getByLabel('Kind').selectOption('curve');
    await curve.getByLabel('Variable').fill(VARIABLE);
    await curve.getByLabel('Tolerance').fill('0.05');
    const scalar = checks.getByRole('group', { name: 'Check 2' });
    await scalar.getByLabel('Check name').fill('Final position');
    await scalar.getByLabel('Points').fill('1');
    await scalar.getByLabel('Kind').selectOption('scalar');
    await scalar.getByLabel('Variable').fill(VARIABLE);
    await scalar.getByLabel('Measure').selectOption('final');
    await scalar.getByLabel('Min').fill('0.65');
    await scalar.getByLabel('Max').fill('0.75');
    // a variable the solution does not log: the server's refusal names the check
    await curve.getByLabel('Variable').fill('Mass#P2#NoSuchVariable');
    await checks.getByRole('button', { name: 'Save checks' }).click();
    await expect(checks.getByTestId('checks-error')).toContainText('Position follows the reference');
    await curve.getByLabel('Variable').fill(VARIABLE);
    await checks.getByRole('button', { name: 'Save checks' }).click();
    await expect(teacher.getByText('Saved 2 checks and the reference run')).toBeVisible({ timeout: 30_000 });
    await expect(checks.getByTestId('checks-error')).toBeEmpty();
    // the page shows the checks as the server stored them
    await expect(teacher.getByRole('form', { name: 'Checks' }).getByRole('group', { name: 'Check 2' }).getByLabel('Min')).toHaveValue('0.65');

    // ---- the students: join, open the copy, tune, save, run, pretest, hand in
    const students: Page[] = [];
    for (const [i, s] of STUDENTS.entries()) {
        const page = await loggedIn(browser, s.name);
        students.push(page);
        await page.getByTestId('nav-classes').click();
        await page.getByLabel('Join code').fill('WRONGCODE234');
        await page.getByRole('button', { name: 'Join', exact: true }).click();
        await expect(page.getByTestId('join-error')).not.toBeEmpty();
        await page.getByLabel('Join code').fill(joinCode);
        await page.getByRole('button', { name: 'Join', exact: true }).click();
        await expect(page.getByTestId('class-name')).toHaveText('Fluid power lab');
        await page.getByRole('link', { name: 'Tune the servo' }).click();
        await expect(page.getByTestId('instructions').locator('h1')).toHaveText('Task');
        await expect(page.getByTestId('student-status')).toHaveAttribute('data-status', 'not_opened');

        await page.getByTestId('open-copy').click();
        await expect(page.getByTestId('model-name')).toBeVisible();
        await expect(page.locator('.canvas .component').first()).toBeVisible();
        await expect(page.getByTestId('save')).toHaveText('Save');
        if (i === 1) {
            // a parameter the assignment does not list takes no input in the copy
            await page.locator('.canvas .component[data-name="GainI"] .icon-frame').click();
            await expect(page.getByLabel('k#Value value')).not.toBeEditable();
        }
        await setGain(page, s.k);
        await page.getByTestId('save').click();
        await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'false');
        await runAndWait(page);

        await expect(page.getByTestId('editor-note')).toContainText('GainP.k');
        await page.getByRole('link', { name: '← Tune the servo' }).click();
        await expect(page.getByTestId('student-status')).toHaveAttribute('data-status', 'ran');
        await page.getByTestId('run-pretests').click();
        const results = page.getByTestId('pretest-results');
        await expect(results.locator('tr[data-check="Position follows the reference"]')).toBeVisible({ timeout: 30_000 });
        if (i === 0) {
            // the solution's gain: the run equals the reference
            await expect(results.locator('tr[data-check="Position follows the reference"] td.outcome')).toHaveAttribute('data-passed', 'true');
            await expect(page.getByTestId('pretest-score')).toHaveText('2 / 2');
            // the editor's "Saved" note may still be up: it is not part of this page
            await page.evaluate(() => document.getElementById('toasts')?.replaceChildren());
            await page.screenshot({ path: `${docsScreenshots}lab-assignment.png`, fullPage: true });
        }
        await page.getByTestId('hand-in').click();
        const history = page.getByTestId('handin-history');
        await expect(history.locator('.handin[data-attempt="1"]')).toBeVisible({ timeout: 30_000 });
        await expect(history.locator('.handin[data-attempt="1"] [data-testid="handin-checks"] tr[data-check="Final position"]')).toBeVisible();
        await expect(page.getByTestId('student-status')).toHaveAttribute('data-status', 'handed_in');
    }

    // ---- the teacher's dashboard: both handed in, scores, two series in the overlay
    expect(teacher.url()).toBe(assignmentUrl);
    await teacher.reload();
    const board = teacher.getByTestId('dashboard-table');
    for (const s of STUDENTS) {
        const row = board.locator(`tr[data-student="${s.name}"]`);
        await expect(row.getByTestId('row-status')).toHaveAttribute('data-status', 'handed_in');
        await expect(row.getByTestId('row-score')).toContainText('/ 3');
    }
    await expect(board.locator('tr[data-student="stan"]').getByTestId('row-score')).toHaveText('3 / 3');
    const overlay = teacher.getByTestId('overlay-plot');
    await expect(overlay).toHaveAttribute('data-series', '2');
    await expect(overlay).toHaveAttribute('data-students', /stan/);
    await expect(overlay).toHaveAttribute('data-students', /stella/);
    await expect(overlay.locator('.u-legend')).toContainText('stan');
    await expect(overlay.locator('.u-legend')).toContainText('stella');

    // a comment on stan's hand-in
    await board.locator('tr[data-student="stan"]').getByRole('button', { name: 'Hand-ins' }).click();
    const details = board.locator('tr[data-details-for="stan"]');
    await expect(details.locator('[data-testid="handin-checks"] tr[data-check="Final position"]')).toBeVisible();
    await details.getByLabel('Comment', { exact: true }).fill('Well tuned: no overshoot to speak of.');
    await details.getByRole('button', { name: 'Comment', exact: true }).click();
    await expect(details.getByTestId('comments')).toContainText('Well tuned');
    // the dashboard section with a margin around it
    const box = (await teacher.getByTestId('dashboard').boundingBox())!;
    const [scrollX, scrollY] = await teacher.evaluate(() => [window.scrollX, window.scrollY]);
    await teacher.screenshot({ path: `${docsScreenshots}lab-dashboard.png`, fullPage: true,
        clip: { x: box.x + scrollX - 16, y: box.y + scrollY - 12, width: box.width + 32, height: box.height + 24 } });

    // the teacher's grade overrides the score
    await details.getByLabel('Grade', { exact: true }).fill('2.5');
    await details.getByRole('button', { name: 'Set grade' }).click();
    await expect(board.locator('tr[data-student="stan"]').getByTestId('row-grade')).toHaveText('2.5');

    // a student's copy opens read-only for the teacher
    await board.locator('tr[data-student="stella"]').getByRole('link', { name: 'Open copy' }).click();
    await expect(teacher.locator('.canvas .component').first()).toBeVisible();
    await expect(teacher.getByTestId('save')).toHaveText('Save as my copy');
    await teacher.getByRole('link', { name: '← Tune the servo' }).click();
    await expect(teacher.getByTestId('dashboard-table')).toBeVisible();

    // the student reads the comment
    await students[0].reload();
    await expect(students[0].getByTestId('handin-history').getByTestId('comments')).toContainText('Well tuned: no overshoot to speak of.');
    await expect(students[0].getByTestId('handin-history').getByTestId('comments')).toContainText(TEACHER);

    // ---- a new template: a changed copy keeps the student's work until reset
    await teacher.goto(assignmentUrl);
    await teacher.getByRole('button', { name: 'Edit assignment' }).click();
    const edit = teacher.getByRole('form', { name: 'Edit assignment' });
    await edit.getByLabel('Template model').selectOption({ label: 'Position Servo' });
    await edit.getByRole('button', { name: 'Save changes' }).click();
    await expect(teacher.getByText('Assignment saved')).toBeVisible();
    const stella = students[1];
    stella.on('dialog', (d) => void d.accept());
    await stella.reload();
    await expect(stella.getByTestId('outdated')).toContainText('version 2');
    await stella.getByTestId('reset-copy').click();
    await expect(stella.getByTestId('outdated')).toHaveCount(0);
    await expect(stella.getByTestId('student-work')).toContainText('template version 2');

    // ---- the gradebook, as a file
    await teacher.goto(classUrl);
    const [download] = await Promise.all([teacher.waitForEvent('download'), teacher.getByTestId('export-gradebook').click()]);
    expect(download.suggestedFilename()).toMatch(/gradebook\.csv$/);
    const csv = readFileSync((await download.path())!, 'utf8');
    const lines = csv.trim().split(/\r?\n/);
    expect(lines[0]).toContain('Tune the servo');
    expect(lines.find((l) => l.startsWith('stan,'))).toContain('2.5');
    expect(lines.some((l) => l.startsWith('stella,'))).toBe(true);

    for (const page of [teacher, ...students]) await page.context().close();
});

test('a class\'s members: import accounts, change a role, remove a student, archive', async ({ browser, request }) => {
    const login = await request.post(`${baseUrl()}/api/v1/auth/login`, { data: { username: 'admin', password: ADMIN_PASSWORD } });
    const { token } = await login.json() as { token: string };
    const created = await request.post(`${baseUrl()}/api/v1/users`, {
        headers: { Authorization: `Bearer ${token}` }, data: { username: 'terry', password: password('terry'), role: 'teacher' },
    });
    expect(created.status()).toBe(201);
    const teacher = await loggedIn(browser, 'terry');
    teacher.on('dialog', (d) => void d.accept());
    await teacher.getByTestId('nav-classes').click();
    await teacher.getByLabel('Class name').fill('Hydraulics 2');
    await teacher.getByRole('button', { name: 'Create class' }).click();
    await expect(teacher.getByTestId('class-name')).toHaveText('Hydraulics 2');
    const joinCode = (await teacher.getByTestId('join-code').textContent())!.trim();

    // a new account and an existing one (alice, from the suite's setup)
    await teacher.getByLabel('User names to import').fill('username\nnewbie\nalice\n');
    await teacher.getByRole('button', { name: 'Import accounts' }).click();
    const result = teacher.getByTestId('import-result');
    await expect(result.locator('tr[data-username="newbie"]')).toContainText('new');
    await expect(result.locator('tr[data-username="alice"]')).toContainText('existing');
    const newbiePassword = (await result.locator('tr[data-username="newbie"] code.password').textContent())!.trim();
    expect(newbiePassword.length).toBeGreaterThanOrEqual(8);

    // the new account logs in with the password shown once and finds the class
    const newbieContext = await browser.newContext();
    const newbie = await newbieContext.newPage();
    await newbie.goto(`${baseUrl()}/#/login`);
    await newbie.getByLabel('User name').fill('newbie');
    await newbie.getByLabel('Password').fill(newbiePassword);
    await newbie.getByRole('button', { name: 'Log in' }).click();
    await expect(newbie.getByRole('heading', { name: 'Examples' })).toBeVisible();
    await newbie.getByTestId('nav-classes').click();
    await expect(newbie.getByTestId('class-list').locator('tr', { hasText: 'Hydraulics 2' })).toContainText('student');

    // alice assists; newbie is removed and loses the class at once
    await result.getByRole('button', { name: 'Done' }).click();
    const members = teacher.getByTestId('members-table');
    await members.getByLabel('Role of alice').selectOption('assistant');
    await expect(members.getByLabel('Role of alice')).toHaveValue('assistant');
    await members.locator('tr[data-username="newbie"]').getByRole('button', { name: 'Remove' }).click();
    await expect(members.locator('tr[data-username="newbie"]')).toHaveCount(0);
    await newbie.reload();
    await expect(newbie.getByTestId('class-list')).not.toContainText('Hydraulics 2');

    // archived: read-only, no joins
    await teacher.getByTestId('archive-toggle').click();
    await expect(teacher.getByTestId('archived')).toBeVisible();
    await expect(teacher.getByTestId('new-assignment')).toHaveCount(0);
    await newbie.getByLabel('Join code').fill(joinCode);
    await newbie.getByRole('button', { name: 'Join', exact: true }).click();
    await expect(newbie.getByTestId('join-error')).toContainText('archived');
    // wrong codes: after ten the server says to wait, and the page says so
    for (let i = 0; i < 10; i++) {
        await newbie.getByLabel('Join code').fill(`WRONG${String(i).padStart(7, 'X')}`);
        await newbie.getByRole('button', { name: 'Join', exact: true }).click();
        await expect(newbie.getByRole('button', { name: 'Join', exact: true })).toBeEnabled();
    }
    await newbie.getByLabel('Join code').fill('WRONGCODEAGN');
    await newbie.getByRole('button', { name: 'Join', exact: true }).click();
    await expect(newbie.getByTestId('join-error')).toContainText('Too many wrong codes');
    await newbieContext.close();
    await teacher.context().close();
});
