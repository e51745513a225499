// Assignment instructions as Markdown, rendered safely: raw HTML in the text is escaped
// (html: false), and markdown-it's link check refuses javascript:, vbscript:, file: and data:
// (except images) URLs, which then stay plain text. Links open in a new tab without giving
// it a handle on this one (rel="noopener noreferrer").
import MarkdownIt from 'markdown-it';
import { h } from '../ui/dom';

const md = new MarkdownIt({ html: false, linkify: true, typographer: false });

const defaultLinkOpen = md.renderer.rules.link_open
    ?? ((tokens, idx, options, _env, self) => self.renderToken(tokens, idx, options));
md.renderer.rules.link_open = (tokens, idx, options, env, self) => {
    const token = tokens[idx];
    token.attrSet('target', '_blank');
    token.attrSet('rel', 'noopener noreferrer');
    return defaultLinkOpen(tokens, idx, options, env, self);
};

/** The HTML of a Markdown text (safe to put into a page). */
export function renderMarkdown(text: string): string {
    return md.render(text);
}

/** A block showing the Markdown text. */
export function markdownBlock(text: string, attrs: Record<string, unknown> = {}): HTMLElement {
    const block = h('div', { class: 'markdown', ...attrs });
    block.innerHTML = renderMarkdown(text);
    return block;
}
