// Issue 39 item 7: a teacher who bounds a parameter so that the template's own value lies
// outside is warned in words, on the assignment's page and in its form.
import { test, expect } from './fixtures';
import { baseUrl, loginWith } from './helpers';
import { ADMIN_PASSWORD } from './globalSetup';

const TEACHER = 'wanda';
const PASSWORD = 'wanda-warning-password';

test('a teacher is warned that the template lies outside the bounds they set', async ({ page, request }) => {
    const call = async (path: string, data: object, token: string) => {
        const response = await request.post(`${baseUrl()}/api/v1${path}`, { headers: { Authorization: `Bearer ${token}` }, data });
        expect(response.ok(), `POST ${path}: ${await response.text()}`).toBe(true);
        return response.json() as Promise<Record<string, unknown>>;
    };
    const login = async (username: string, password: string) =>
        (await call('/auth/login', { username, password }, '')).token as string;
    await call('/users', { username: TEACHER, password: PASSWORD, role: 'teacher' }, await login('admin', ADMIN_PASSWORD));
    const theClass = await call('/classes', { name: 'Warned class' }, await login(TEACHER, PASSWORD));

    await loginWith(page, TEACHER, PASSWORD);
    await page.goto(`${baseUrl()}/#/class/${String(theClass.id)}`);

    // Position Servo's GainP.k is 0.0264249: above the maximum 0.01 set here.
    await page.getByTestId('new-assignment').click();
    const form = page.getByRole('form', { name: 'New assignment' });
    await form.getByLabel('Title').fill('Gain below the template');
    await form.getByLabel('Template model').selectOption({ label: 'Position Servo (example)' });
    await form.getByRole('button', { name: 'Add parameter' }).click();
    await form.getByLabel('Parameter 1 name').fill('GainP.k');
    await form.getByLabel('Parameter 1 min').fill('0');
    await form.getByLabel('Parameter 1 max').fill('0.01');
    await form.getByRole('button', { name: 'Create assignment' }).click();

    await expect(page.getByTestId('assignment-title')).toHaveText('Gain below the template');
    const warnings = page.getByTestId('assignment-warnings');
    await expect(warnings).toContainText('Check this before students start');
    await expect(warnings.locator('li[data-code="template_outside_bounds"]')).toHaveText(
        'The template sets GainP.k to 0.0264249, outside the bounds you set (between 0 and 0.01). '
        + 'Students start outside the bounds: change the bounds, or save the template with a value inside them.');

    // The form that changes the assignment says it too.
    await page.getByRole('button', { name: 'Edit assignment' }).click();
    await expect(page.getByRole('form', { name: 'Edit assignment' }).getByTestId('assignment-warnings'))
        .toContainText('The template sets GainP.k to 0.0264249');
});
