// @vitest-environment jsdom
// The instructions' Markdown renders what teachers write (headings, emphasis, lists, code,
// links) and nothing that runs: raw HTML is text, script URLs are no links.
import { describe, expect, it } from 'vitest';
import { markdownBlock, renderMarkdown } from './markdown';

function dom(text: string): HTMLElement {
    return markdownBlock(text);
}

/** Nothing in the rendered DOM could run script. */
function expectInert(el: HTMLElement): void {
    expect(el.querySelectorAll('script, iframe, object, embed, style')).toHaveLength(0);
    for (const node of el.querySelectorAll('*')) {
        for (const attr of node.attributes) {
            expect(attr.name.toLowerCase().startsWith('on'), `${node.tagName} ${attr.name}`).toBe(false);
            if (['href', 'src', 'action', 'formaction', 'xlink:href'].includes(attr.name.toLowerCase())) {
                expect(attr.value.replace(/[\s\u0000-\u001f]/g, '').toLowerCase()).not.toMatch(/^(javascript|vbscript|data:text|file):/);
            }
        }
    }
}

describe('markdown', () => {
    it('has an inertness check that would see script', () => {
        const bad = document.createElement('div');
        bad.innerHTML = '<a href=" JavaScript:alert(1)">x</a>';
        expect(() => expectInert(bad)).toThrow();
        bad.innerHTML = '<img src="x" onerror="alert(1)">';
        expect(() => expectInert(bad)).toThrow();
    });

    it.each([
        '<script>alert(1)</script>',
        '<img src=x onerror=alert(1)>',
        '[x](javascript:alert(1))',
        '[x](JAVASCRIPT:alert(1))',
        '[x](  jAvAsCrIpT:alert(1) )',
        '[x](vbscript:msgbox(1))',
        '[x](file:///etc/passwd)',
        '[x](data:text/html;base64,PHNjcmlwdD5hbGVydCgxKTwvc2NyaXB0Pg==)',
        '<a href="javascript:alert(1)">x</a>',
        '<a href="javascript:alert(1)" onclick="alert(2)">x</a>',
        '[x][ref]\n\n[ref]: javascript:alert(1)',
        '<javascript:alert(1)>',
        '![x](javascript:alert(1))',
        '<svg onload=alert(1)>',
        '```html\n<script>alert(1)</script>\n```',
    ])('renders %j inert', (text) => {
        const el = dom(text);
        expectInert(el);
    });

    it('shows raw HTML as text', () => {
        const el = dom('<script>alert(1)</script>');
        expect(el.querySelector('script')).toBeNull();
        expect(el.textContent).toContain('<script>alert(1)</script>');
        const img = dom('<img src=x onerror=alert(1)>');
        expect(img.querySelector('img')).toBeNull();
        expect(img.textContent).toContain('onerror');
    });

    it('keeps a javascript: link as text, not as a link', () => {
        for (const text of ['[x](javascript:alert(1))', '[x](JAVASCRIPT:alert(1))', '<a href="javascript:...">x</a>']) {
            const el = dom(text);
            expect(el.querySelector('a'), text).toBeNull();
        }
    });

    it('renders headings, emphasis, lists, code and http links', () => {
        const el = dom([
            '# Task',
            '',
            'Set **P** so that the *overshoot* stays small.',
            '',
            '- first',
            '- second',
            '',
            '1. one',
            '2. two',
            '',
            'Use `GainP.k`:',
            '',
            '```',
            'k = 0.01',
            '```',
            '',
            'See [the manual](https://example.org/manual?a=1&b=2) and http://example.com/x.',
        ].join('\n'));
        expect(el.querySelector('h1')?.textContent).toBe('Task');
        expect(el.querySelector('strong')?.textContent).toBe('P');
        expect(el.querySelector('em')?.textContent).toBe('overshoot');
        expect([...el.querySelectorAll('ul > li')].map((li) => li.textContent)).toEqual(['first', 'second']);
        expect(el.querySelectorAll('ol > li')).toHaveLength(2);
        expect(el.querySelector('p > code')?.textContent).toBe('GainP.k');
        expect(el.querySelector('pre > code')?.textContent).toBe('k = 0.01\n');
        const links = [...el.querySelectorAll('a')];
        expect(links.map((a) => a.getAttribute('href'))).toEqual(['https://example.org/manual?a=1&b=2', 'http://example.com/x']);
        for (const a of links) {
            expect(a.getAttribute('rel')).toBe('noopener noreferrer');
            expect(a.getAttribute('target')).toBe('_blank');
        }
        expectInert(el);
    });

    it('keeps data: images (markdown-it allows those) as images only', () => {
        const html = renderMarkdown('![dot](data:image/png;base64,iVBORw0KGgo=)');
        expect(html).toContain('<img src="data:image/png;base64,iVBORw0KGgo="');
    });
});
