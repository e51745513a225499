// A small LTI 1.3 platform (a stand-in for Moodle or Canvas) for tlmhub's LTI tool tests: LTI 1.3
// Core launches, Deep Linking 2.0 and Assignment and Grade Services 2.0, on npm's jose for the JWTs,
// served over TLS on loopback. The test writes a JSON file and passes its path:
//   {"port", "certFile", "keyFile", "clientId", "deploymentId",
//    "tool": {"loginUrl", "launchUrl", "jwksUrl"}}
// The issuer is https://127.0.0.1:<port>. Endpoints the tool uses: GET /jwks, GET|POST /auth,
// POST /token, /courses/<ctx>/lineitems[/<id>[/scores|/results]], POST /deep-link-return.
// Control endpoints for the test (JSON, no authentication, loopback only):
//   POST /control/launch {user, context, messageType, resourceLink, targetLinkUri, custom,
//        lineItem, ags, deepLinkingSettings, tamper} -> {loginUrl, lineitem}
//   POST /control/rotate-key -> {kid}; POST /control/down, /control/up -> {down}
//   GET /control/scores, /control/deep-links, /control/lineitems, /control/log
// GET /course?launch=<tool login URL> is a course page that frames the tool as Moodle and Canvas
// embed it. README.md gives the shapes. Prints "ready" once it listens.
import { readFileSync } from 'node:fs';
import https from 'node:https';
import { createRemoteJWKSet, exportJWK, generateKeyPair } from 'jose';
import { handleAgs, handleToken } from './ags.mjs';
import { controlLaunch, handleAuth, handleDeepLinkReturn } from './launch.mjs';
import { escapeHtml, parseJson, readBody, refuse, sendHtml, sendJson, simplePage } from './web.mjs';

const config = JSON.parse(readFileSync(process.argv[2], 'utf8'));
for (const name of ['port', 'certFile', 'keyFile', 'clientId', 'deploymentId'])
    if (config[name] === undefined) throw new Error(`config: ${name} is missing`);
for (const name of ['loginUrl', 'launchUrl', 'jwksUrl'])
    if (!config.tool?.[name]) throw new Error(`config: tool.${name} is missing`);

const issuer = `https://127.0.0.1:${config.port}`;
let counter = 0;
const platform = {
    config, issuer, tokenUrl: `${issuer}/token`,
    keys: [],                       // signing keys, the current one first; the JWKS publishes them all
    // The tool's keys; no cool-down, so a key the tool has just rotated in is fetched at once.
    toolJwks: createRemoteJWKSet(new URL(config.tool.jwksUrl), { cooldownDuration: 0, cacheMaxAge: 10_000 }),
    launches: new Map(),            // login_hint -> pending launch
    contexts: new Map(),            // course id -> {id, title, label, lineItems}
    resourceLinks: new Map(),       // resource link id -> link placed by deep linking
    deepLinkRequests: new Map(),    // settings data -> {launch, answered}
    tokens: new Map(),              // access token -> {scopes, expires}
    seenJti: new Map(),             // client assertion jti -> exp (replays are refused)
    scores: [], deepLinks: [], log: [],
    down: false,
    strangerKey: undefined,         // the key of the "unknownKey" tamper, made on first use
    nextNumber: () => ++counter,
};

// A new RS256 key becomes current; the previous one stays published so tokens already signed verify.
async function rotateKey() {
    const { privateKey, publicKey } = await generateKeyPair('RS256', { modulusLength: 2048 });
    const kid = `platform-key-${Date.now()}-${platform.nextNumber()}`;
    const publicJwk = { ...(await exportJWK(publicKey)), kid, alg: 'RS256', use: 'sig' };
    platform.keys = [{ kid, privateKey, publicJwk }, ...platform.keys.slice(0, 1)];
    return kid;
}

// /control/log: each request to /auth, /token, AGS and /deep-link-return with its outcome.
function track(kind, req, res, url) {
    res.on('finish', () => platform.log.push({
        at: new Date().toISOString(), kind, method: req.method, path: url.pathname + url.search,
        status: res.statusCode, ...(res.note && { note: res.note }),
    }));
}

async function control(req, res, url) {
    const remote = req.socket.remoteAddress ?? '';
    if (!['127.0.0.1', '::1', '::ffff:127.0.0.1'].includes(remote))
        return refuse(res, 403, 'forbidden', 'control endpoints are for loopback only');
    const route = `${req.method} ${url.pathname}`;
    switch (route) {
        case 'POST /control/launch': {
            const body = parseJson((await readBody(req)) || '{}');
            if (!body || typeof body !== 'object') return refuse(res, 400, 'invalid_request', 'the body is not a JSON object');
            return sendJson(res, 200, await controlLaunch(platform, body));
        }
        case 'POST /control/rotate-key': return sendJson(res, 200, { kid: await rotateKey() });
        case 'POST /control/down': platform.down = true; return sendJson(res, 200, { down: true });
        case 'POST /control/up': platform.down = false; return sendJson(res, 200, { down: false });
        case 'GET /control/scores': return sendJson(res, 200, platform.scores);
        case 'GET /control/deep-links': return sendJson(res, 200, platform.deepLinks);
        case 'GET /control/log': return sendJson(res, 200, platform.log);
        case 'GET /control/lineitems':
            return sendJson(res, 200, [...platform.contexts.values()].flatMap((c) =>
                [...c.lineItems.values()].map((e) => ({ ...e.item, results: [...e.results.values()] }))));
        default: return refuse(res, 404, 'not_found', `no control endpoint ${route}`);
    }
}

// GET /course?launch=<url>: a course's page with the tool in a frame, as Moodle ("Embed") and
// Canvas place an LTI link: the frame starts at the tool's login initiation URL (the loginUrl
// that /control/launch answers). The course is the launch's context when the URL names a pending
// launch (login_hint). No sandbox and no `allow`, as those platforms do.
function coursePage(res, url) {
    const launch = url.searchParams.get('launch');
    let target;
    try {
        target = new URL(launch ?? '');
    } catch {
        return refuse(res, 400, 'invalid_request', 'launch must be the URL the frame opens');
    }
    if (target.protocol !== 'http:' && target.protocol !== 'https:')
        return refuse(res, 400, 'invalid_request', 'launch must be an http(s) URL');
    const pending = platform.launches.get(target.searchParams.get('login_hint'));
    const title = pending?.context.title ?? 'Course';
    sendHtml(res, 200, `<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>Course</title>
<style>body { font-family: sans-serif; margin: 1rem 2rem; } iframe { border: 1px solid #999; }</style></head>
<body>
  <h1>${escapeHtml(title)}</h1>
  <p>The course's page on the test LTI platform. The activity below is the tool, embedded.</p>
  <iframe src="${escapeHtml(target.href)}" title="Activity" width="100%" height="700"></iframe>
</body></html>
`);
}

async function handle(req, res) {
    const url = new URL(req.url, issuer);
    const path = url.pathname;
    if (path === '/jwks' && req.method === 'GET')
        return sendJson(res, 200, { keys: platform.keys.map((k) => k.publicJwk) }, 'application/jwk-set+json');
    if (path.startsWith('/control/')) return control(req, res, url);
    if (path === '/auth' && (req.method === 'GET' || req.method === 'POST')) {
        track('auth', req, res, url);
        return handleAuth(platform, req, res, url);
    }
    if (path === '/deep-link-return' && req.method === 'POST') {
        track('deep-link-return', req, res, url);
        return handleDeepLinkReturn(platform, req, res);
    }
    const service = path === '/token' ? 'token' : path.startsWith('/courses/') ? 'ags' : null;
    if (service) {
        track(service, req, res, url);
        // While "down" the services fail the way an overloaded platform does, so the tool retries.
        if (platform.down) return refuse(res, 503, 'temporarily_unavailable', 'the platform is down', { 'Retry-After': '1' });
        if (service === 'token') {
            if (req.method !== 'POST') return refuse(res, 405, 'invalid_request', 'the token endpoint takes POST');
            return handleToken(platform, req, res);
        }
        return handleAgs(platform, req, res, url);
    }
    if (path === '/course' && req.method === 'GET') return coursePage(res, url);
    if (path === '/launch-return' && req.method === 'GET') {
        const shown = [...url.searchParams].map(([k, v]) => `<li>${escapeHtml(k)}: ${escapeHtml(v)}</li>`).join('');
        return sendHtml(res, 200, simplePage('Back at the platform', `<ul>${shown}</ul>`));
    }
    refuse(res, 404, 'not_found', `no endpoint ${req.method} ${path}`);
}

await rotateKey();
https.createServer({ cert: readFileSync(config.certFile), key: readFileSync(config.keyFile) }, (req, res) => {
    handle(req, res).catch((err) => {
        if (res.headersSent) return res.destroy();
        refuse(res, err.status ?? 500, err.status ? 'invalid_request' : 'server_error', err.message);
    });
}).listen(config.port, '127.0.0.1', () => console.log('ready'));
