// A student's locked copy looks locked (docs/labs.md "Locks"): only the parameter the
// assignment lists takes input, with its bounds beside it; the palette is gone and the other
// fields are read-only; a value out of bounds goes back to the last good one with the reason;
// the instructions are beside the editor. And the teacher's gradebook is a table in the page
// that sorts by a column click. Classes, assignments and hand-ins are made through the API.
import { test, expect, type APIRequestContext, type Browser, type Page } from './fixtures';
import { fileURLToPath } from 'node:url';
import { baseUrl, loginWith } from './helpers';
import { ADMIN_PASSWORD } from './globalSetup';

const docsScreenshots = fileURLToPath(new URL('../../docs/screenshots/', import.meta.url));
const password = (user: string) => `${user}-locked-password`;
const INSTRUCTIONS = '# Tune the servo\nSet the **proportional gain** `GainP.k` so that the mass follows the step without a large overshoot.\n\n1. Change `GainP.k` (between 0 and 0.1).\n2. Run, save, pretest and hand in.';

/** A REST call as one user; the reply as JSON (these are the API's own shapes, read loosely). */
type Call = (method: string, path: string, data?: unknown) => Promise<any>;

async function as(request: APIRequestContext, username: string, secret = password(username)): Promise<Call> {
    const login = await request.post(`${baseUrl()}/api/v1/auth/login`, { data: { username, password: secret } });
    expect(login.ok(), `login ${username}`).toBe(true);
    const { token } = await login.json() as { token: string };
    return async (method, path, data) => {
        const response = await request.fetch(`${baseUrl()}/api/v1${path}`, { method, data, headers: { Authorization: `Bearer ${token}` } });
        expect(response.ok(), `${method} ${path}: ${await response.text()}`).toBe(true);
        if (response.status() === 204) return null;
        return (response.headers()['content-type'] ?? '').includes('json') ? response.json() : response.text();
    };
}

/**
 * A teacher, students who joined, and an assignment on Position Servo (or on the model
 * `template` makes of it as the teacher) that lets them change GainP.k within 0 … 0.1.
 */
async function lockedAssignment(request: APIRequestContext, prefix: string, students: string[],
    template?: (teacher: Call, servoId: number) => Promise<number>) {
    const admin = await as(request, 'admin', ADMIN_PASSWORD);
    const teacherName = `${prefix}teacher`;
    for (const [username, role] of [[teacherName, 'teacher'], ...students.map((s) => [s, 'user'])]) {
        await admin('POST', '/users', { username, password: password(username), role });
    }
    const teacher = await as(request, teacherName);
    const models = await teacher('GET', '/models') as { id: number; name: string; is_example: boolean }[];
    const servo = models.find((m) => m.is_example && m.name === 'Position Servo')!;
    const theClass = await teacher('POST', '/classes', { name: 'Fluid power lab' });
    const templateId = template ? await template(teacher, servo.id) : servo.id;
    const assignment = await teacher('POST', `/classes/${theClass.id}/assignments`, {
        title: 'Tune the servo', instructions: INSTRUCTIONS, template_model_id: templateId,
        edit_mode: 'parameters', parameters: [{ name: 'GainP.k', min: 0, max: 0.1 }],
    });
    const copies = new Map<string, { call: Call; modelId: number }>();
    for (const s of students) {
        const call = await as(request, s);
        await call('POST', '/classes/join', { code: theClass.join_code });
        const { copy } = await call('POST', `/assignments/${assignment.id}/open`);
        copies.set(s, { call, modelId: copy.model_id });
    }
    return { teacher, teacherName, classId: theClass.id as number, assignmentId: assignment.id as number, copies };
}

async function loggedIn(browser: Browser, username: string): Promise<Page> {
    const page = await (await browser.newContext()).newPage();
    await loginWith(page, username, password(username));
    return page;
}

test('a student\'s locked copy: only the allowed field takes input, a refused value returns with the reason', async ({ browser, request }) => {
    const { assignmentId, copies } = await lockedAssignment(request, 'lc', ['lcstudent']);
    const page = await loggedIn(browser, 'lcstudent');
    await page.goto(`${baseUrl()}/#/model/${copies.get('lcstudent')!.modelId}?assignment=${assignmentId}`);
    await expect(page.locator('.canvas .component').first()).toBeVisible();
    const components = await page.locator('.canvas .component').count();

    // the instructions beside the editor; no palette to add from
    await expect(page.getByTestId('instructions-panel').locator('h1')).toHaveText('Tune the servo');
    await expect(page.locator('.palette')).toHaveCount(0);

    // the allowed parameter takes input, its bounds beside it; structural buttons are off
    await page.locator('.canvas .component[data-name="GainP"] .icon-frame').click();
    const gain = page.getByLabel('k#Value value');
    await expect(gain).toBeEditable();
    await expect(page.getByTestId('param-bounds')).toHaveText('allowed: 0 … 0.1');
    await expect(page.getByLabel('Component name')).not.toBeEditable();
    for (const name of ['Rotate', 'Flip', 'Delete']) await expect(page.locator('.parameter-panel').getByRole('button', { name, exact: true })).toBeDisabled();
    await gain.fill('0.05');
    await gain.press('Enter');
    await expect(page.getByTestId('dirty')).toHaveAttribute('data-dirty', 'true');
    await expect(page.locator('.parameter-panel .field-error')).toHaveCount(0);

    // out of bounds: back to the last good value, the reason beside it
    await gain.fill('5');
    await gain.press('Enter');
    await expect(page.locator('.parameter-panel .field-error')).toHaveText('GainP.k#Value must stay within 0 … 0.1');
    await expect(gain).toHaveValue('0.05');
    await page.screenshot({ path: `${docsScreenshots}locked-copy.png` });

    // another component's parameter is read-only, and a delete key changes nothing
    await page.locator('.canvas .component[data-name="GainI"] .icon-frame').click();
    await expect(page.getByLabel('k#Value value')).not.toBeEditable();
    await page.keyboard.press('Delete');
    await expect(page.getByTestId('editor-messages').getByRole('alert')).toContainText('Only the parameters this assignment lists');
    await expect(page.locator('.canvas .component')).toHaveCount(components);

    // a drag does not even start to move a component: the press stays a click (it selects)
    const body = page.locator('.canvas .component[data-name="Pressure_Relief_Valve"] .icon-frame');
    const centre = async () => {
        const box = (await body.boundingBox())!;
        return { x: Math.round(box.x + box.width / 2), y: Math.round(box.y + box.height / 2) };
    };
    const start = await centre();
    await page.mouse.move(start.x, start.y);
    await page.mouse.down();
    await page.mouse.move(start.x + 80, start.y + 40, { steps: 5 });
    expect(await centre()).toEqual(start);
    await page.mouse.up();
    expect(await centre()).toEqual(start);
});

test('the teacher\'s gradebook is a table that sorts by a column click', async ({ browser, request }) => {
    const students = ['gbsam', 'gbstan', 'gbstella'];
    const { teacher, teacherName, classId, assignmentId, copies } = await lockedAssignment(request, 'gb', students);
    // two hand in; the teacher grades them (the gradebook takes the grade over the score)
    for (const [student, grade] of [['gbstella', 4], ['gbstan', 2.5]] as const) {
        const handIn = await copies.get(student)!.call('POST', `/assignments/${assignmentId}/handin`);
        await teacher('PUT', `/handins/${handIn.id}/grade`, { grade });
    }
    const page = await loggedIn(browser, teacherName);
    await page.goto(`${baseUrl()}/#/class/${classId}`);
    const table = page.getByTestId('gradebook-table');
    const order = () => table.locator('tbody tr').evaluateAll((rows) => rows.map((r) => r.getAttribute('data-username')));
    await expect(table.locator('tbody tr')).toHaveCount(3);
    expect(await order()).toEqual(students);
    await table.getByRole('button', { name: 'Total' }).click();
    await expect(table.locator('th[data-column="total"]')).toHaveAttribute('aria-sort', 'descending');
    expect(await order()).toEqual(['gbstella', 'gbstan', 'gbsam']);
    await expect(table.locator('tr[data-username="gbstella"]')).toContainText('4');
    const box = (await page.getByTestId('gradebook').boundingBox())!;
    await page.screenshot({ path: `${docsScreenshots}gradebook-table.png`, clip: { x: box.x - 12, y: box.y - 12, width: box.width + 24, height: box.height + 24 } });
});

/**
 * The teacher's template: Position Servo running for 60 s, with two sliders in its GUI data (as
 * the editor saves them): one for the step's amplitude, one for the proportional gain up to 0.5.
 */
async function servoWithControls(teacher: Call, servoId: number): Promise<number> {
    const shown = await teacher('GET', `/models/${servoId}`) as { model: { system: { components: { name: string; pose: { x: number; y: number } }[] } } };
    const at = (name: string) => shown.model.system.components.find((c) => c.name === name)!.pose;
    const [step, gain] = [at('Step'), at('GainP')];
    const controls = `<tlmhub_livecontrols>`
        + `<control kind="slider" name="Step.y_A" min="0" max="1" x="${step.x}" y="${step.y + 70}"/>`
        + `<control kind="slider" name="GainP.k" min="0" max="0.5" x="${gain.x}" y="${gain.y - 90}"/>`
        + `</tlmhub_livecontrols>`;
    const hmf = (await teacher('GET', `/models/${servoId}?format=hmf`) as string)
        .replace(/(<simulationtime[^>]*\bstop=")[^"]*/, '$160')
        .replace('<hopsangui>', `<hopsangui>${controls}`);
    const created = await teacher('POST', '/models', { name: 'Position Servo with controls', hmf });
    return created.id as number;
}

test("a student's live session on a locked copy: the template's controls, only the listed value acts, within its bounds", async ({ browser, request }) => {
    const { assignmentId, copies } = await lockedAssignment(request, 'lv', ['lvstudent'], servoWithControls);
    const page = await loggedIn(browser, 'lvstudent');
    // live.set requests as sent, and the replies that refused one
    const sets: { name: string; value: number }[] = [];
    const refusals: string[] = [];
    let sessionId = 0;
    page.on('websocket', (ws) => {
        ws.on('framesent', ({ payload }) => {
            if (typeof payload === 'string' && payload.includes('"live.set"')) sets.push(JSON.parse(payload) as { name: string; value: number });
        });
        ws.on('framereceived', ({ payload }) => {
            if (typeof payload !== 'string') return;
            const message = JSON.parse(payload) as { ok?: boolean; data?: { session_id?: number }; error?: { code: string } };
            if (message.ok === false) refusals.push(message.error?.code ?? '?');
            if (message.ok && message.data?.session_id) sessionId = message.data.session_id;
        });
    });
    await page.goto(`${baseUrl()}/#/model/${copies.get('lvstudent')!.modelId}?assignment=${assignmentId}`);
    const gain = page.locator('[data-testid="live-control"][data-name="GainP.k"]');
    const step = page.locator('[data-testid="live-control"][data-name="Step.y_A"]');
    // the template's controls are in the copy, and the student cannot change or remove them
    await expect(gain).toBeVisible();
    await expect(step).toBeVisible();
    await expect(page.locator('.live-control-edit, .live-control-remove')).toHaveCount(0);

    await page.getByTestId('live').click();
    await expect(page.getByTestId('live-status')).toContainText('Live');
    // only the listed value acts, its range cut to the assignment's bounds
    await expect(step).toHaveClass(/unavailable/);
    await expect(step.getByTestId('live-control-input')).toBeDisabled();
    const input = gain.getByTestId('live-control-input');
    await expect(input).toBeEnabled();
    await expect(input).toHaveAttribute('max', '0.1');

    // dragged to its far end, the gain goes to the bound and the server takes it
    const box = (await input.boundingBox())!;
    await page.mouse.move(box.x + 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width + 40, box.y + box.height / 2, { steps: 6 });
    await page.mouse.up();
    await expect.poll(() => sets.at(-1)).toEqual(expect.objectContaining({ name: 'GainP.k', value: 0.1 }));
    expect(sets.every((s) => s.name === 'GainP.k' && s.value >= 0 && s.value <= 0.1)).toBe(true);
    await expect(page.getByTestId('live-status')).toContainText('Live');
    expect(refusals).toEqual([]);
    await page.screenshot({ path: `${docsScreenshots}live-locked-copy.png` });

    // what the page does not offer, the server refuses: the step's amplitude, and the gain out of bounds
    expect(sessionId).toBeGreaterThan(0);
    const codes = await page.evaluate(async (id) => {
        type Ws = { request(type: string, fields: unknown): Promise<unknown> };
        const ws = (window as unknown as { __tlmhub: { ws: Ws } }).__tlmhub.ws;
        const codeOf = (p: Promise<unknown>) => p.then(() => 'ok', (e: { code?: string }) => e.code ?? String(e));
        return [await codeOf(ws.request('live.set', { session_id: id, name: 'Step.y_A', value: 0.5 })),
            await codeOf(ws.request('live.set', { session_id: id, name: 'GainP.k', value: 0.4 }))];
    }, sessionId);
    expect(codes).toEqual(['locked', 'locked']);
    await page.getByTestId('live-stop').click();
});
