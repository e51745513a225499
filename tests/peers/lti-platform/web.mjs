// Small HTTP helpers shared by the platform's modules (no framework: node:https only).

export const MAX_BODY = 1 << 20;

// The request body as text; refuses bodies over MAX_BODY so a runaway client cannot fill memory.
export function readBody(req) {
    return new Promise((resolve, reject) => {
        const chunks = [];
        let size = 0;
        req.on('data', (chunk) => {
            size += chunk.length;
            if (size > MAX_BODY) {
                reject(Object.assign(new Error('request body too large'), { status: 413 }));
                req.destroy();
            } else chunks.push(chunk);
        });
        req.on('end', () => resolve(Buffer.concat(chunks).toString('utf8')));
        req.on('error', reject);
    });
}

// application/x-www-form-urlencoded text as a plain object (the last value wins for repeated names).
export function parseForm(text) {
    return Object.fromEntries(new URLSearchParams(text));
}

// The JSON body, or undefined when it is not JSON.
export function parseJson(text) {
    try {
        return JSON.parse(text);
    } catch {
        return undefined;
    }
}

// The media type of the request body without parameters ("; charset=utf-8"), lower case.
export function mediaType(req) {
    return (req.headers['content-type'] ?? '').split(';')[0].trim().toLowerCase();
}

// True when the client asked for JSON (the C++ tests, which have no browser to run a form).
export function wantsJson(req) {
    return (req.headers.accept ?? '').toLowerCase().includes('application/json');
}

export function sendJson(res, status, body, type = 'application/json', headers = {}) {
    const text = body === undefined ? '' : JSON.stringify(body, null, 2);
    res.writeHead(status, { 'Content-Type': type, 'Cache-Control': 'no-store', ...headers });
    res.end(text);
}

export function sendHtml(res, status, html) {
    res.writeHead(status, { 'Content-Type': 'text/html; charset=utf-8', 'Cache-Control': 'no-store' });
    res.end(html);
}

// A JSON error in the OAuth shape ({error, error_description}); `res.note` is what /control/log shows.
export function refuse(res, status, error, description, headers = {}) {
    res.note = `${error}: ${description}`;
    sendJson(res, status, { error, error_description: description }, 'application/json', headers);
}

export function escapeHtml(text) {
    return String(text).replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

// A page that posts `fields` to `action` as soon as it loads (how platforms hand a browser over).
export function autoPostPage(action, fields, title = 'Launching') {
    const inputs = Object.entries(fields)
        .map(([name, value]) => `<input type="hidden" name="${escapeHtml(name)}" value="${escapeHtml(value)}">`)
        .join('\n    ');
    return `<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>${escapeHtml(title)}</title></head>
<body>
  <form method="post" action="${escapeHtml(action)}">
    ${inputs}
    <noscript><button type="submit">Continue</button></noscript>
  </form>
  <script>document.forms[0].submit();</script>
</body></html>
`;
}

export function simplePage(title, body) {
    return `<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>${escapeHtml(title)}</title></head>
<body><h1>${escapeHtml(title)}</h1>${body}</body></html>
`;
}
