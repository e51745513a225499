// Self-test of the LTI platform: starts platform.mjs with a throw-away certificate and a fake tool
// (a node:http server with its own key pair) and walks launch, deep linking, the token endpoint and
// AGS the way a tool does. `node selftest.mjs`; exits 1 when a check fails.
import { execFileSync, spawn } from 'node:child_process';
import { randomUUID } from 'node:crypto';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import http from 'node:http';
import https from 'node:https';
import net from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createLocalJWKSet, decodeProtectedHeader, exportJWK, generateKeyPair, jwtVerify, SignJWT } from 'jose';

const LTI = 'https://purl.imsglobal.org/spec/lti/claim/';
const LTI_DL = 'https://purl.imsglobal.org/spec/lti-dl/claim/';
const AGS = 'https://purl.imsglobal.org/spec/lti-ags/claim/endpoint';
const SCOPE = {
    lineitem: 'https://purl.imsglobal.org/spec/lti-ags/scope/lineitem',
    score: 'https://purl.imsglobal.org/spec/lti-ags/scope/score',
    result: 'https://purl.imsglobal.org/spec/lti-ags/scope/result.readonly',
};
const CLIENT_ID = 'tlmhub-client';
const DEPLOYMENT_ID = 'deployment-1';

let passed = 0;
const failures = [];
function check(condition, what, detail) {
    if (condition) {
        passed++;
        console.log(`ok - ${what}`);
    } else {
        failures.push(what);
        console.log(`FAIL - ${what}${detail === undefined ? '' : `: ${typeof detail === 'string' ? detail : JSON.stringify(detail)}`}`);
    }
}

function freePort() {
    return new Promise((resolve) => {
        const s = net.createServer().listen(0, '127.0.0.1', () => {
            const { port } = s.address();
            s.close(() => resolve(port));
        });
    });
}

// --- the platform, over TLS with a certificate made for this run ---------------------------------
const dir = mkdtempSync(join(tmpdir(), 'lti-platform-selftest-'));
execFileSync('openssl', ['req', '-x509', '-newkey', 'rsa:2048', '-nodes', '-subj', '/CN=127.0.0.1',
    '-addext', 'subjectAltName=IP:127.0.0.1', '-days', '1', '-keyout', join(dir, 'key.pem'), '-out', join(dir, 'cert.pem')],
    { stdio: 'ignore' });
const ca = readFileSync(join(dir, 'cert.pem'));  // the self-signed certificate is its own CA

// One request; https URLs trust only this run's certificate. Answers {status, headers, text, json}.
function request(url, { method = 'GET', headers = {}, body } = {}) {
    const target = new URL(url);
    const lib = target.protocol === 'https:' ? https : http;
    return new Promise((resolve, reject) => {
        const req = lib.request(target, { method, headers, ...(target.protocol === 'https:' && { ca }) }, (res) => {
            const chunks = [];
            res.on('data', (c) => chunks.push(c));
            res.on('end', () => {
                const text = Buffer.concat(chunks).toString('utf8');
                let json;
                try { json = JSON.parse(text); } catch { /* not JSON */ }
                resolve({ status: res.statusCode, headers: res.headers, text, json });
            });
        });
        req.on('error', reject);
        if (body !== undefined) req.write(body);
        req.end();
    });
}
const postForm = (url, fields, headers = {}) => request(url, { method: 'POST',
    headers: { 'Content-Type': 'application/x-www-form-urlencoded', ...headers }, body: new URLSearchParams(fields).toString() });
const postJson = (url, body, type = 'application/json', headers = {}) =>
    request(url, { method: 'POST', headers: { 'Content-Type': type, ...headers }, body: JSON.stringify(body) });

// --- the fake tool: JWKS, login initiation (redirects to /auth) and the launch URL ----------------
const toolKey = await generateKeyPair('RS256', { modulusLength: 2048 });
const toolJwk = { ...(await exportJWK(toolKey.publicKey)), kid: 'tool-key-1', alg: 'RS256', use: 'sig' };
const strangerKey = await generateKeyPair('RS256', { modulusLength: 2048 });
const toolPort = await freePort();
const platformPort = await freePort();
const issuer = `https://127.0.0.1:${platformPort}`;
const tool = {
    loginUrl: `http://127.0.0.1:${toolPort}/api/v1/lti/login`,
    launchUrl: `http://127.0.0.1:${toolPort}/api/v1/lti/launch`,
    jwksUrl: `http://127.0.0.1:${toolPort}/api/v1/lti/jwks`,
};
const toolStates = new Map();  // state -> nonce, as a tool keeps them
const toolLaunches = [];       // forms posted to the launch URL
const toolServer = http.createServer((req, res) => {
    const url = new URL(req.url, `http://127.0.0.1:${toolPort}`);
    if (url.pathname === '/api/v1/lti/jwks') {
        res.writeHead(200, { 'Content-Type': 'application/json' }).end(JSON.stringify({ keys: [toolJwk] }));
    } else if (url.pathname === '/api/v1/lti/login') {
        const state = randomUUID();
        const nonce = randomUUID();
        toolStates.set(state, nonce);
        const auth = new URL(`${url.searchParams.get('iss')}/auth`);
        for (const [k, v] of Object.entries({
            scope: 'openid', response_type: 'id_token', response_mode: 'form_post', prompt: 'none',
            client_id: url.searchParams.get('client_id'), redirect_uri: tool.launchUrl,
            login_hint: url.searchParams.get('login_hint'), lti_message_hint: url.searchParams.get('lti_message_hint'),
            state, nonce,
        })) auth.searchParams.set(k, v);
        res.writeHead(302, { Location: auth.href }).end();
    } else if (url.pathname === '/api/v1/lti/launch' && req.method === 'POST') {
        const chunks = [];
        req.on('data', (c) => chunks.push(c));
        req.on('end', () => {
            toolLaunches.push(Object.fromEntries(new URLSearchParams(Buffer.concat(chunks).toString())));
            res.writeHead(200, { 'Content-Type': 'text/plain' }).end('launched');
        });
    } else res.writeHead(404).end();
});
await new Promise((resolve) => toolServer.listen(toolPort, '127.0.0.1', resolve));

const configFile = join(dir, 'config.json');
writeFileSync(configFile, JSON.stringify({ port: platformPort, certFile: join(dir, 'cert.pem'), keyFile: join(dir, 'key.pem'),
    clientId: CLIENT_ID, deploymentId: DEPLOYMENT_ID, tool }));
const child = spawn(process.execPath, [new URL('./platform.mjs', import.meta.url).pathname, configFile],
    { stdio: ['ignore', 'pipe', 'pipe'] });
let childOutput = '';
child.stderr.on('data', (d) => { childOutput += d; });
await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`the platform did not start: ${childOutput}`)), 20000);
    child.stdout.on('data', (d) => {
        childOutput += d;
        if (childOutput.includes('ready')) { clearTimeout(timer); resolve(); }
    });
    child.on('exit', (code) => reject(new Error(`the platform ended (${code}): ${childOutput}`)));
});

function finish() {
    child.kill();
    toolServer.close();
    rmSync(dir, { recursive: true, force: true });
    console.log(failures.length ? `\nselftest: ${passed} passed, ${failures.length} FAILED: ${failures.join('; ')}`
                                : `\nselftest: all ${passed} checks passed`);
    process.exit(failures.length ? 1 : 0);
}

try {
    await run();
} catch (err) {
    failures.push(`exception: ${err.stack}`);
    console.log(err.stack);
}
finish();

// --- the walk ------------------------------------------------------------------------------------

// control/launch, then the tool's login initiation, which redirects to /auth. Answers the /auth URL.
async function startLaunch(body) {
    const started = await postJson(`${issuer}/control/launch`, body);
    if (started.status !== 200) throw new Error(`control/launch: ${started.status} ${started.text}`);
    const login = await request(started.json.loginUrl);
    const authUrl = new URL(login.headers.location);
    return { ...started.json, authUrl, state: authUrl.searchParams.get('state'), nonce: authUrl.searchParams.get('nonce') };
}
async function authJson(authUrl) {
    return (await request(authUrl, { headers: { Accept: 'application/json' } })).json;
}
async function platformKeys() {
    return createLocalJWKSet((await request(`${issuer}/jwks`)).json);
}
async function verifyMessage(idToken) {
    return (await jwtVerify(idToken, await platformKeys(), { issuer, audience: CLIENT_ID, algorithms: ['RS256'] })).payload;
}
async function refusesMessage(idToken, expectedNonce, deployment = DEPLOYMENT_ID) {
    try {
        const claims = await verifyMessage(idToken);
        // Claims a tool checks beyond the signature and the standard JWT claims.
        return claims.nonce !== expectedNonce || claims[`${LTI}deployment_id`] !== deployment || claims[`${LTI}version`] !== '1.3.0'
            || !['LtiResourceLinkRequest', 'LtiDeepLinkingRequest'].includes(claims[`${LTI}message_type`]);
    } catch {
        return true;
    }
}
function clientAssertion({ aud = `${issuer}/token`, jti = randomUUID(), key = toolKey.privateKey, iss = CLIENT_ID, exp = '5m' } = {}) {
    return new SignJWT({ jti }).setProtectedHeader({ alg: 'RS256', kid: toolJwk.kid }).setIssuer(iss).setSubject(CLIENT_ID)
        .setAudience(aud).setIssuedAt().setExpirationTime(exp).sign(key);
}
async function askToken(assertion, scope = Object.values(SCOPE).join(' '), grant = 'client_credentials') {
    return postForm(`${issuer}/token`, { grant_type: grant, client_assertion_type: 'urn:ietf:params:oauth:client-assertion-type:jwt-bearer',
        client_assertion: assertion, scope });
}
function deepLinkResponse(claims, key = toolKey.privateKey) {
    return new SignJWT({ nonce: randomUUID(), [`${LTI}message_type`]: 'LtiDeepLinkingResponse', [`${LTI}version`]: '1.3.0',
        [`${LTI}deployment_id`]: DEPLOYMENT_ID, ...claims })
        .setProtectedHeader({ alg: 'RS256', kid: toolJwk.kid }).setIssuer(CLIENT_ID).setAudience(issuer)
        .setIssuedAt().setExpirationTime('5m').sign(key);
}

async function run() {
    // The platform's keys.
    const jwks = (await request(`${issuer}/jwks`)).json;
    const first = jwks.keys[0];
    check(jwks.keys.length === 1 && first.kty === 'RSA' && first.alg === 'RS256' && first.use === 'sig' && first.kid && !first.d,
          'JWKS publishes one public RS256 signing key with a kid', jwks);

    // A resource link launch with a line item, all the way through the tool's login initiation.
    const launch = await startLaunch({
        user: { sub: 'student-7', name: 'Grace Brewster Hopper', email: 'grace@example.org', roles: ['Learner'] },
        context: { id: 'math-101', title: 'Mathematics 101' }, resourceLink: { id: 'rl-1', title: 'Pendulum lab' },
        custom: { lab: 'pendulum' }, lineItem: { scoreMaximum: 10, label: 'Pendulum lab' },
    });
    const login = new URL((await postJson(`${issuer}/control/launch`, {})).json.loginUrl);
    check(login.origin + login.pathname === tool.loginUrl && login.searchParams.get('iss') === issuer
          && login.searchParams.get('login_hint') && login.searchParams.get('lti_message_hint')
          && login.searchParams.get('target_link_uri') === tool.launchUrl && login.searchParams.get('client_id') === CLIENT_ID
          && login.searchParams.get('lti_deployment_id') === DEPLOYMENT_ID, 'control/launch answers the login initiation URL', login.href);
    check(launch.lineitem === `${issuer}/courses/math-101/lineitems/1`, 'control/launch creates the line item', launch.lineitem);

    const answer = await authJson(launch.authUrl);
    check(answer.action === tool.launchUrl && answer.state === launch.state && answer.id_token, '/auth answers action, id_token and state', answer);
    const header = decodeProtectedHeader(answer.id_token);
    const claims = await verifyMessage(answer.id_token);
    check(header.alg === 'RS256' && header.kid === first.kid, 'the id_token is RS256 with the kid of the current key', header);
    const now = Date.now() / 1000;
    check(claims.sub === 'student-7' && claims.nonce === launch.nonce && claims.azp === CLIENT_ID
          && claims.exp > now + 200 && claims.exp <= now + 301 && claims.iat <= now + 1, 'sub, nonce, azp, iat, exp', claims);
    check(claims.name === 'Grace Brewster Hopper' && claims.given_name === 'Grace' && claims.family_name === 'Brewster Hopper'
          && claims.email === 'grace@example.org', 'name, given_name, family_name, email');
    check(claims[`${LTI}message_type`] === 'LtiResourceLinkRequest' && claims[`${LTI}version`] === '1.3.0'
          && claims[`${LTI}deployment_id`] === DEPLOYMENT_ID && claims[`${LTI}target_link_uri`] === tool.launchUrl,
          'message_type, version, deployment_id, target_link_uri');
    check(JSON.stringify(claims[`${LTI}resource_link`]) === JSON.stringify({ id: 'rl-1', title: 'Pendulum lab' }), 'resource_link');
    check(JSON.stringify(claims[`${LTI}roles`]) === JSON.stringify(['http://purl.imsglobal.org/vocab/lis/v2/membership#Learner']), 'roles as IRIs');
    const ctx = claims[`${LTI}context`];
    check(ctx.id === 'math-101' && ctx.title === 'Mathematics 101' && ctx.label && Array.isArray(ctx.type), 'context', ctx);
    check(claims[`${LTI}tool_platform`]?.guid && claims[`${LTI}launch_presentation`]?.document_target === 'iframe'
          && claims[`${LTI}launch_presentation`]?.return_url, 'tool_platform and launch_presentation');
    check(claims[`${LTI}custom`]?.lab === 'pendulum', 'custom');
    const endpoint = claims[AGS];
    check(endpoint?.lineitem === launch.lineitem && endpoint?.lineitems === `${issuer}/courses/math-101/lineitems`
          && Object.values(SCOPE).every((s) => endpoint.scope.includes(s)), 'the AGS endpoint claim', endpoint);
    check(!claims[`${LTI_DL}deep_linking_settings`], 'no deep linking settings in a resource link launch');

    // The browser variant: a page that posts the form to the tool.
    const page = await request(launch.authUrl);
    const action = /<form method="post" action="([^"]+)"/.exec(page.text)?.[1];
    const fields = Object.fromEntries([...page.text.matchAll(/<input type="hidden" name="([^"]+)" value="([^"]*)">/g)].map((m) => [m[1], m[2]]));
    check(page.headers['content-type'].startsWith('text/html') && action === tool.launchUrl && fields.id_token && fields.state === launch.state
          && page.text.includes('.submit()'), 'without Accept JSON /auth answers an auto-posting form');
    await postForm(action, fields);
    check(toolLaunches.length === 1 && toolLaunches[0].state === launch.state, 'the form posts id_token and state to the tool');

    // Refusals at /auth.
    const variant = (changes) => {
        const u = new URL(launch.authUrl);
        for (const [k, v] of Object.entries(changes)) v === null ? u.searchParams.delete(k) : u.searchParams.set(k, v);
        return u;
    };
    const wrongRedirect = await request(variant({ redirect_uri: 'http://127.0.0.1:1/evil' }), { headers: { Accept: 'application/json' } });
    check(wrongRedirect.status === 400 && !wrongRedirect.text.includes('id_token'), 'an unregistered redirect_uri is refused with 400', wrongRedirect.status);
    const wrongClient = await request(variant({ client_id: 'someone' }), { headers: { Accept: 'application/json' } });
    check(wrongClient.status === 400 && wrongClient.json.error === 'unauthorized_client', 'an unknown client_id is refused with 400 unauthorized_client');
    for (const [changes, error] of [
        [{ nonce: null }, 'invalid_request'], [{ state: null }, 'invalid_request'], [{ prompt: null }, 'invalid_request'],
        [{ response_type: 'code' }, 'unsupported_response_type'], [{ scope: 'profile' }, 'invalid_scope'],
        [{ response_mode: 'query' }, 'invalid_request'], [{ login_hint: 'nobody' }, 'login_required'],
        [{ lti_message_hint: 'other' }, 'invalid_request'],
    ]) {
        const refused = await authJson(variant(changes));
        check(refused.action === tool.launchUrl && refused.error === error && !refused.id_token
              && (changes.state === null || refused.state === launch.state), `/auth with ${JSON.stringify(changes)} answers ${error}`, refused);
    }

    // Tampered messages: each one fails the checks a tool makes.
    for (const tamper of [
        { claims: { aud: 'someone-else' } }, { claims: { iss: 'https://evil.example' } }, { claims: { deployment_id: 'deployment-2' } },
        { claims: { version: '1.1' } }, { claims: { message_type: 'LtiSomethingElse' } }, { claims: { exp: '-600', iat: '-900' } },
        { claims: { nonce: 'not-the-tools-nonce' } }, { claims: { [`${LTI}message_type`]: null } }, { signWith: 'unknownKey' },
        { alg: 'none' }, { kid: 'missing' },
    ]) {
        const l = await startLaunch({ tamper });
        const t = await authJson(l.authUrl);
        check(t.id_token && await refusesMessage(t.id_token, l.nonce), `tamper ${JSON.stringify(tamper)} makes the message invalid`);
    }
    const noneHeader = decodeProtectedHeader((await authJson((await startLaunch({ tamper: { alg: 'none' } })).authUrl)).id_token);
    check(noneHeader.alg === 'none', 'tamper alg none is unsigned');
    const noKid = decodeProtectedHeader((await authJson((await startLaunch({ tamper: { kid: null } })).authUrl)).id_token);
    check(noKid.alg === 'RS256' && !('kid' in noKid), 'tamper kid null leaves the kid out');
    const stateTamper = await startLaunch({ tamper: { state: 'forged' } });
    check((await authJson(stateTamper.authUrl)).state === 'forged', 'tamper state changes the state posted back');
    const roleLaunch = await startLaunch({ user: { sub: 'teacher', roles: ['Instructor', 'Administrator', 'http://purl.imsglobal.org/vocab/lis/v2/membership#Mentor'] } });
    const roles = (await verifyMessage((await authJson(roleLaunch.authUrl)).id_token))[`${LTI}roles`];
    check(JSON.stringify(roles) === JSON.stringify(['http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor',
        'http://purl.imsglobal.org/vocab/lis/v2/institution/person#Administrator', 'http://purl.imsglobal.org/vocab/lis/v2/membership#Mentor']),
          'short role names become IRIs, full IRIs stay', roles);

    // The token endpoint.
    const assertion = await clientAssertion();
    const granted = await askToken(assertion);
    check(granted.status === 200 && granted.json.token_type === 'Bearer' && granted.json.expires_in === 3600 && granted.json.access_token
          && granted.json.scope.split(' ').length === 3, 'a signed client assertion gets a Bearer token', granted.json);
    const bearer = { Authorization: `Bearer ${granted.json.access_token}` };
    const replay = await askToken(assertion);
    check(replay.status === 401 && replay.json.error === 'invalid_client', 'a replayed jti is refused (invalid_client)', replay.json);
    const wrongAud = await askToken(await clientAssertion({ aud: 'https://elsewhere/token' }));
    check(wrongAud.status === 401 && wrongAud.json.error === 'invalid_client', 'a wrong aud is refused (invalid_client)', wrongAud.json);
    const wrongIss = await askToken(await clientAssertion({ iss: 'someone' }));
    check(wrongIss.status === 401 && wrongIss.json.error === 'invalid_client', 'a wrong iss is refused (invalid_client)');
    const expired = await askToken(await clientAssertion({ exp: Math.floor(Date.now() / 1000) - 120 }));
    check(expired.status === 401 && expired.json.error === 'invalid_client', 'an expired assertion is refused (invalid_client)');
    const forged = await askToken(await clientAssertion({ key: strangerKey.privateKey }));
    check(forged.status === 401 && forged.json.error === 'invalid_client', 'an assertion signed by another key is refused');
    const badScope = await askToken(await clientAssertion(), `${SCOPE.score} https://purl.imsglobal.org/spec/lti-nrps/scope/contextmembership.readonly`);
    check(badScope.status === 400 && badScope.json.error === 'invalid_scope', 'an unknown scope is refused (invalid_scope)', badScope.json);
    const badGrant = await askToken(await clientAssertion(), SCOPE.score, 'password');
    check(badGrant.status === 400 && badGrant.json.error === 'unsupported_grant_type', 'another grant type is refused');

    // AGS.
    const li = await request(launch.lineitem, { headers: bearer });
    check(li.status === 200 && li.headers['content-type'] === 'application/vnd.ims.lis.v2.lineitem+json' && li.json.id === launch.lineitem
          && li.json.scoreMaximum === 10 && li.json.resourceLinkId === 'rl-1', 'GET line item', li.json);
    const noToken = await request(launch.lineitem);
    check(noToken.status === 401 && noToken.headers['www-authenticate']?.startsWith('Bearer'), 'AGS without a token: 401');
    const scoreOnly = (await askToken(await clientAssertion(), SCOPE.score)).json.access_token;
    check((await request(launch.lineitem, { headers: { Authorization: `Bearer ${scoreOnly}` } })).status === 403, 'AGS without the scope: 403');
    const lineitems = endpoint.lineitems;
    const created = await postJson(lineitems, { scoreMaximum: 5, label: 'Extra', tag: 'bonus', resourceId: 'r-9' },
                                   'application/vnd.ims.lis.v2.lineitem+json', bearer);
    check(created.status === 201 && created.json.id === `${lineitems}/2` && created.json.label === 'Extra', 'POST line item: 201 with id', created.json);
    check((await postJson(lineitems, { scoreMaximum: 5, label: 'x' }, 'application/json', bearer)).status === 415, 'POST line item with the wrong media type: 415');
    check((await postJson(lineitems, { scoreMaximum: 0, label: 'x' }, 'application/vnd.ims.lis.v2.lineitem+json', bearer)).status === 400,
          'POST line item with scoreMaximum 0: 400');
    const container = await request(lineitems, { headers: bearer });
    check(container.status === 200 && container.headers['content-type'] === 'application/vnd.ims.lis.v2.lineitemcontainer+json'
          && container.json.length === 2, 'GET line item container', container.json);
    const byTag = await request(`${lineitems}?tag=bonus`, { headers: bearer });
    check(byTag.json.length === 1 && byTag.json[0].label === 'Extra', 'the container filters by tag');

    const SCORE = 'application/vnd.ims.lis.v1.score+json';
    const t1 = new Date(Date.now() - 5000).toISOString();
    const score = { userId: 'student-7', scoreGiven: 7.5, scoreMaximum: 10, activityProgress: 'Completed', gradingProgress: 'FullyGraded',
                    timestamp: t1, comment: 'well done' };
    const posted = await postJson(`${launch.lineitem}/scores`, score, SCORE, bearer);
    check(posted.status === 204, 'POST score: 204', posted.status);
    check((await postJson(`${launch.lineitem}/scores`, score, 'application/json', bearer)).status === 415, 'a score with the wrong media type: 415');
    for (const [change, what] of [
        [{ activityProgress: 'Done' }, 'an unknown activityProgress'], [{ gradingProgress: 'Graded' }, 'an unknown gradingProgress'],
        [{ scoreGiven: -1 }, 'a negative scoreGiven'], [{ scoreMaximum: undefined }, 'scoreGiven without scoreMaximum'],
        [{ userId: undefined }, 'no userId'], [{ timestamp: 'yesterday' }, 'a timestamp not ISO 8601'],
    ]) {
        const r = await postJson(`${launch.lineitem}/scores`, { ...score, ...change, timestamp: change.timestamp ?? new Date().toISOString() }, SCORE, bearer);
        check(r.status === 400 && r.json.error === 'invalid_request', `a score with ${what}: 400`, r.status);
    }
    const results = await request(`${launch.lineitem}/results`, { headers: bearer });
    const r0 = results.json?.[0];
    check(results.status === 200 && results.headers['content-type'] === 'application/vnd.ims.lis.v2.resultcontainer+json'
          && results.json.length === 1 && r0.userId === 'student-7' && r0.resultScore === 7.5 && r0.resultMaximum === 10
          && r0.scoreOf === launch.lineitem && r0.id && r0.timestamp === t1 && r0.comment === 'well done', 'GET results', results.json);
    const older = await postJson(`${launch.lineitem}/scores`, { ...score, scoreGiven: 9, timestamp: new Date(Date.now() - 60000).toISOString() }, SCORE, bearer);
    check(older.status === 409, 'a score older than the one on record: 409', older.status);
    check((await postJson(`${launch.lineitem}/scores`, { ...score, scoreGiven: 9 }, SCORE, bearer)).status === 409, 'a score with the same timestamp: 409');
    const newer = await postJson(`${launch.lineitem}/scores`, { ...score, scoreGiven: 9, timestamp: new Date().toISOString() }, SCORE, bearer);
    const after = (await request(`${launch.lineitem}/results?user_id=student-7`, { headers: bearer })).json;
    check(newer.status === 204 && after.length === 1 && after[0].resultScore === 9, 'a newer score replaces the result', after);
    check((await request(`${launch.lineitem}/results?user_id=nobody`, { headers: bearer })).json.length === 0, 'results filter by user_id');
    const stored = (await request(`${issuer}/control/scores`)).json;
    check(stored.length === 2 && stored[0].lineitem === launch.lineitem && stored[0].score.scoreGiven === 7.5, 'control/scores lists the accepted scores');

    // Down and up again.
    await request(`${issuer}/control/down`, { method: 'POST' });
    const downToken = await askToken(await clientAssertion());
    const downAgs = await request(launch.lineitem, { headers: bearer });
    const downJwks = await request(`${issuer}/jwks`);
    check(downToken.status === 503 && downAgs.status === 503 && downJwks.status === 200, 'down: /token and AGS 503, the rest works');
    await request(`${issuer}/control/up`, { method: 'POST' });
    check((await askToken(await clientAssertion())).status === 200 && (await request(launch.lineitem, { headers: bearer })).status === 200,
          'up: /token and AGS answer again');

    // Deep linking.
    const dl = await startLaunch({ messageType: 'LtiDeepLinkingRequest', user: { sub: 'teacher-1', roles: ['Instructor'] },
                                   context: { id: 'math-101' } });
    const dlClaims = await verifyMessage((await authJson(dl.authUrl)).id_token);
    const settings = dlClaims[`${LTI_DL}deep_linking_settings`];
    check(dlClaims[`${LTI}message_type`] === 'LtiDeepLinkingRequest' && !dlClaims[`${LTI}resource_link`]
          && settings?.deep_link_return_url === `${issuer}/deep-link-return` && settings.accept_types[0] === 'ltiResourceLink'
          && settings.accept_multiple === false && settings.auto_create === true && settings.data
          && settings.accept_presentation_document_targets.includes('iframe'), 'the deep linking request and its settings', settings);
    const items = [{ type: 'ltiResourceLink', title: 'Spring lab', url: `${tool.launchUrl}?lab=spring`, custom: { lab: 'spring' },
                     lineItem: { scoreMaximum: 20, label: 'Spring lab', resourceId: 'lab-spring', tag: 'lab' } }];
    const returnUrl = settings.deep_link_return_url;
    const wrongData = await postForm(returnUrl, { JWT: await deepLinkResponse({ [`${LTI_DL}data`]: 'forged', [`${LTI_DL}content_items`]: items }) });
    check(wrongData.status === 400 && wrongData.text.includes('data'), 'a deep linking response with other data is refused', wrongData.status);
    const wrongType = await postForm(returnUrl, { JWT: await deepLinkResponse({ [`${LTI_DL}data`]: settings.data, [`${LTI_DL}content_items`]: items,
                                                                                [`${LTI}message_type`]: 'LtiResourceLinkRequest' }) });
    check(wrongType.status === 400, 'a deep linking response with another message type is refused');
    const wrongKey = await postForm(returnUrl, { JWT: await deepLinkResponse({ [`${LTI_DL}data`]: settings.data, [`${LTI_DL}content_items`]: items },
                                                                             strangerKey.privateKey) });
    check(wrongKey.status === 400, 'a deep linking response signed by another key is refused');
    const two = await postForm(returnUrl, { JWT: await deepLinkResponse({ [`${LTI_DL}data`]: settings.data, [`${LTI_DL}content_items`]: [...items, ...items] }) });
    check(two.status === 400, 'two items are refused when accept_multiple is false');
    const placed = await postForm(returnUrl, { JWT: await deepLinkResponse({ [`${LTI_DL}data`]: settings.data, [`${LTI_DL}content_items`]: items,
                                                                             [`${LTI_DL}msg`]: 'Placed one lab' }) });
    check(placed.status === 200 && placed.text.includes('Content placed'), 'the deep linking response places the content', placed.status);
    const again = await postForm(returnUrl, { JWT: await deepLinkResponse({ [`${LTI_DL}data`]: settings.data, [`${LTI_DL}content_items`]: items }) },
                                 { Accept: 'application/json' });
    check(again.status === 400 && again.json.error === 'invalid_request', 'a second response to the same request is refused');
    const links = (await request(`${issuer}/control/deep-links`)).json;
    const link = links[0]?.placed[0];
    check(links.length === 1 && link?.title === 'Spring lab' && link.lineitem === `${issuer}/courses/math-101/lineitems/3`
          && links[0].claims[`${LTI_DL}msg`] === 'Placed one lab', 'control/deep-links shows the items and the line item made for them', links);
    const linkLaunch = await startLaunch({ resourceLink: { id: link.resourceLinkId }, context: { id: 'math-101' } });
    const linkClaims = await verifyMessage((await authJson(linkLaunch.authUrl)).id_token);
    check(linkClaims[`${LTI}target_link_uri`] === link.url && linkClaims[`${LTI}custom`]?.lab === 'spring'
          && linkClaims[AGS]?.lineitem === link.lineitem && linkClaims[`${LTI}resource_link`]?.title === 'Spring lab',
          'launching the placed link uses its url, custom and line item');

    // The course page that frames the tool.
    const framed = await postJson(`${issuer}/control/launch`, { context: { id: 'art-1', title: 'Art & <Design>' } });
    const course = await request(`${issuer}/course?launch=${encodeURIComponent(framed.json.loginUrl)}`);
    const frameSrc = /<iframe src="([^"]*)"/.exec(course.text)?.[1]?.replaceAll('&#38;', '&');
    check(course.status === 200 && course.headers['content-type'].startsWith('text/html') && course.text.includes('<title>Course</title>')
          && course.text.includes('<h1>Art &#38; &#60;Design&#62;</h1>') && frameSrc === framed.json.loginUrl
          && !/sandbox|allow=/.test(course.text), 'GET /course frames the login URL under the course title', course.text);
    check((await request(`${issuer}/course?launch=javascript:alert(1)`)).status === 400 && (await request(`${issuer}/course`)).status === 400,
          'GET /course refuses a launch that is not an http(s) URL');

    // Key rotation.
    const { kid } = (await postJson(`${issuer}/control/rotate-key`, {})).json;
    const rotated = (await request(`${issuer}/jwks`)).json.keys.map((k) => k.kid);
    check(kid && kid !== first.kid && rotated.length === 2 && rotated[0] === kid && rotated.includes(first.kid), 'rotate-key keeps the old kid in the JWKS', rotated);
    const afterRotation = await authJson((await startLaunch({})).authUrl);
    check(decodeProtectedHeader(afterRotation.id_token).kid === kid && await verifyMessage(afterRotation.id_token), 'messages are signed with the new key');
    check(await verifyMessage(answer.id_token), 'a message signed with the old key still verifies');

    // The log.
    const log = (await request(`${issuer}/control/log`)).json;
    const tokenRequests = log.filter((e) => e.kind === 'token');
    check(tokenRequests.some((e) => e.status === 200 && e.note?.startsWith('issued')) && tokenRequests.some((e) => e.status === 503)
          && log.some((e) => e.kind === 'auth') && log.some((e) => e.kind === 'ags' && e.status === 409)
          && log.some((e) => e.kind === 'deep-link-return' && e.status === 200), 'control/log records auth, token, AGS and deep-link-return');
}
