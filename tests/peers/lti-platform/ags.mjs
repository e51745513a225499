// The services side of the platform: the OAuth 2 token endpoint (IMS Security Framework 1.0
// §4.1, RFC 7523 client assertions) and Assignment and Grade Services 2.0 (line items, scores,
// results) for each course ("context").
import { randomBytes } from 'node:crypto';
import { jwtVerify } from 'jose';
import { mediaType, parseForm, parseJson, readBody, refuse, sendJson } from './web.mjs';

export const SCOPES = {
    lineitem: 'https://purl.imsglobal.org/spec/lti-ags/scope/lineitem',
    score: 'https://purl.imsglobal.org/spec/lti-ags/scope/score',
    resultReadonly: 'https://purl.imsglobal.org/spec/lti-ags/scope/result.readonly',
};
const ALLOWED_SCOPES = new Set(Object.values(SCOPES));
const MEDIA = {
    lineItem: 'application/vnd.ims.lis.v2.lineitem+json',
    lineItemContainer: 'application/vnd.ims.lis.v2.lineitemcontainer+json',
    score: 'application/vnd.ims.lis.v1.score+json',
    resultContainer: 'application/vnd.ims.lis.v2.resultcontainer+json',
};
// AGS 2.0 §3.4.5 and §3.4.6: the only progress values a score may carry.
const ACTIVITY_PROGRESS = new Set(['Initialized', 'Started', 'InProgress', 'Submitted', 'Completed']);
const GRADING_PROGRESS = new Set(['FullyGraded', 'Pending', 'PendingManual', 'Failed', 'NotReady']);
// ISO 8601 date and time with a zone (the spec asks for sub-second precision; it is optional here).
const ISO_8601 = /^\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}(\.\d+)?(Z|[+-]\d{2}:?\d{2})$/;
const TOKEN_LIFETIME = 3600;

// The course of `id`, created on first use (launches create their course).
export function ensureContext(platform, { id, title, label }) {
    let context = platform.contexts.get(id);
    if (!context) {
        context = { id, title: title ?? `Course ${id}`, label: label ?? id, lineItems: new Map(), nextLineItem: 1 };
        platform.contexts.set(id, context);
    }
    return context;
}

export function lineItemsUrl(platform, contextId) {
    return `${platform.issuer}/courses/${encodeURIComponent(contextId)}/lineitems`;
}

// A new gradebook column; `fields` is a line item as AGS 2.0 §3.2 describes it.
export function createLineItem(platform, context, fields) {
    const number = String(context.nextLineItem++);
    const item = {
        id: `${lineItemsUrl(platform, context.id)}/${number}`,
        scoreMaximum: fields.scoreMaximum,
        label: fields.label,
        ...(fields.resourceId !== undefined && { resourceId: fields.resourceId }),
        ...(fields.resourceLinkId !== undefined && { resourceLinkId: fields.resourceLinkId }),
        ...(fields.tag !== undefined && { tag: fields.tag }),
        ...(fields.startDateTime !== undefined && { startDateTime: fields.startDateTime }),
        ...(fields.endDateTime !== undefined && { endDateTime: fields.endDateTime }),
    };
    context.lineItems.set(number, { item, results: new Map() });
    return item;
}

// What is wrong with a line item's fields (AGS 2.0 §3.2: label and a positive scoreMaximum), or null.
export function lineItemProblem(fields) {
    if (!fields || typeof fields !== 'object' || Array.isArray(fields)) return 'the body is not a line item object';
    if (typeof fields.label !== 'string' || fields.label.trim() === '') return 'label must be a non-empty string';
    if (typeof fields.scoreMaximum !== 'number' || !(fields.scoreMaximum > 0)) return 'scoreMaximum must be a number > 0';
    for (const name of ['resourceId', 'resourceLinkId', 'tag'])
        if (fields[name] !== undefined && typeof fields[name] !== 'string') return `${name} must be a string`;
    return null;
}

// POST /token: the client credentials grant with a JWT client assertion signed by the tool.
export async function handleToken(platform, req, res) {
    const form = parseForm(await readBody(req));
    if (form.grant_type !== 'client_credentials')
        return refuse(res, 400, 'unsupported_grant_type', `grant_type must be client_credentials, not ${form.grant_type}`);
    if (form.client_assertion_type !== 'urn:ietf:params:oauth:client-assertion-type:jwt-bearer')
        return refuse(res, 400, 'invalid_request', 'client_assertion_type must be urn:ietf:params:oauth:client-assertion-type:jwt-bearer');
    if (!form.client_assertion) return refuse(res, 400, 'invalid_request', 'client_assertion is missing');

    // RFC 7523 §3 and §3.2: every fault of the assertion is invalid_client.
    const clientId = platform.config.clientId;
    let claims;
    try {
        ({ payload: claims } = await jwtVerify(form.client_assertion, platform.toolJwks, {
            issuer: clientId, subject: clientId, audience: platform.tokenUrl, algorithms: ['RS256'],
            requiredClaims: ['exp', 'iat', 'jti'], clockTolerance: 5,
        }));
    } catch (err) {
        return refuse(res, 401, 'invalid_client', `client assertion refused: ${err.code ?? ''} ${err.message}`.trim());
    }
    const now = Math.floor(Date.now() / 1000);
    if (claims.iat > now + 60) return refuse(res, 401, 'invalid_client', 'client assertion iat is in the future');
    for (const [jti, exp] of platform.seenJti) if (exp < now - 60) platform.seenJti.delete(jti);
    if (platform.seenJti.has(claims.jti)) return refuse(res, 401, 'invalid_client', `client assertion jti ${claims.jti} was already used`);
    platform.seenJti.set(claims.jti, claims.exp);

    const scopes = (form.scope ?? '').split(' ').filter(Boolean);
    if (scopes.length === 0) return refuse(res, 400, 'invalid_scope', 'scope is missing');
    const unknown = scopes.filter((s) => !ALLOWED_SCOPES.has(s));
    if (unknown.length) return refuse(res, 400, 'invalid_scope', `scope not allowed: ${unknown.join(' ')}`);

    const accessToken = randomBytes(32).toString('base64url');
    platform.tokens.set(accessToken, { scopes: new Set(scopes), expires: now + TOKEN_LIFETIME });
    res.note = `issued for ${scopes.join(' ')}`;
    sendJson(res, 200, { access_token: accessToken, token_type: 'Bearer', expires_in: TOKEN_LIFETIME, scope: scopes.join(' ') });
}

// RFC 6750 §3.1: 401 invalid_token without a valid token, 403 insufficient_scope without the scope.
function authorize(platform, req, res, acceptedScopes) {
    const match = /^Bearer\s+(\S+)$/i.exec(req.headers.authorization ?? '');
    const token = match && platform.tokens.get(match[1]);
    if (!token || token.expires < Date.now() / 1000) {
        refuse(res, 401, 'invalid_token', match ? 'unknown or expired access token' : 'a Bearer access token is required',
               { 'WWW-Authenticate': 'Bearer error="invalid_token"' });
        return false;
    }
    if (!acceptedScopes.some((s) => token.scopes.has(s))) {
        refuse(res, 403, 'insufficient_scope', `needs ${acceptedScopes.join(' or ')}`,
               { 'WWW-Authenticate': `Bearer error="insufficient_scope", scope="${acceptedScopes[0]}"` });
        return false;
    }
    return true;
}

// Everything under /courses/<ctx>/lineitems: AGS 2.0 §3.2 (line items), §3.4 (scores), §3.3 (results).
export async function handleAgs(platform, req, res, url) {
    const parts = url.pathname.split('/').slice(1).map(decodeURIComponent);  // courses, ctx, lineitems, id?, sub?
    const context = platform.contexts.get(parts[1]);
    if (parts[0] !== 'courses' || parts[2] !== 'lineitems' || parts.length > 5 || !context)
        return refuse(res, 404, 'not_found', `no such AGS resource: ${url.pathname}`);
    const [, , , number, sub] = parts;
    const method = req.method;

    if (number === undefined) {  // the line item container
        if (method === 'GET') {
            if (!authorize(platform, req, res, [SCOPES.lineitem, `${SCOPES.lineitem}.readonly`])) return;
            const q = url.searchParams;
            let items = [...context.lineItems.values()].map((e) => e.item);
            if (q.has('resource_link_id')) items = items.filter((i) => i.resourceLinkId === q.get('resource_link_id'));
            if (q.has('resource_id')) items = items.filter((i) => i.resourceId === q.get('resource_id'));
            if (q.has('tag')) items = items.filter((i) => i.tag === q.get('tag'));
            if (q.has('limit')) items = items.slice(0, Math.max(0, Number(q.get('limit')) || 0));
            return sendJson(res, 200, items, MEDIA.lineItemContainer);
        }
        if (method === 'POST') {
            if (!authorize(platform, req, res, [SCOPES.lineitem])) return;
            if (mediaType(req) !== MEDIA.lineItem) return refuse(res, 415, 'unsupported_media_type', `Content-Type must be ${MEDIA.lineItem}`);
            const fields = parseJson(await readBody(req));
            const problem = lineItemProblem(fields);
            if (problem) return refuse(res, 400, 'invalid_request', problem);
            const item = createLineItem(platform, context, fields);
            res.note = `created ${item.id}`;
            return sendJson(res, 201, item, MEDIA.lineItem, { Location: item.id });
        }
        return refuse(res, 405, 'method_not_allowed', `${method} is not allowed on a line item container`);
    }

    const entry = context.lineItems.get(number);
    if (!entry) return refuse(res, 404, 'not_found', `no line item ${number} in course ${context.id}`);

    if (sub === undefined) {  // one line item
        if (method === 'GET') {
            if (!authorize(platform, req, res, [SCOPES.lineitem, `${SCOPES.lineitem}.readonly`])) return;
            return sendJson(res, 200, entry.item, MEDIA.lineItem);
        }
        if (method === 'PUT') {
            if (!authorize(platform, req, res, [SCOPES.lineitem])) return;
            if (mediaType(req) !== MEDIA.lineItem) return refuse(res, 415, 'unsupported_media_type', `Content-Type must be ${MEDIA.lineItem}`);
            const fields = parseJson(await readBody(req));
            const problem = lineItemProblem(fields);
            if (problem) return refuse(res, 400, 'invalid_request', problem);
            // §3.2.8: the platform keeps the id and the resource link binding.
            entry.item = { ...fields, id: entry.item.id, ...(entry.item.resourceLinkId !== undefined && { resourceLinkId: entry.item.resourceLinkId }) };
            return sendJson(res, 200, entry.item, MEDIA.lineItem);
        }
        if (method === 'DELETE') {
            if (!authorize(platform, req, res, [SCOPES.lineitem])) return;
            context.lineItems.delete(number);
            res.writeHead(204).end();
            return;
        }
        return refuse(res, 405, 'method_not_allowed', `${method} is not allowed on a line item`);
    }

    if (sub === 'scores' && method === 'POST') return postScore(platform, req, res, entry);
    if (sub === 'results' && method === 'GET') {
        if (!authorize(platform, req, res, [SCOPES.resultReadonly])) return;
        const userFilter = url.searchParams.get('user_id');
        let results = [...entry.results.values()].filter((r) => userFilter === null || r.userId === userFilter);
        if (url.searchParams.has('limit')) results = results.slice(0, Math.max(0, Number(url.searchParams.get('limit')) || 0));
        return sendJson(res, 200, results, MEDIA.resultContainer);
    }
    return refuse(res, 404, 'not_found', `no such AGS resource: ${method} ${url.pathname}`);
}

// What is wrong with a score (AGS 2.0 §3.4), or null.
function scoreProblem(score) {
    if (!score || typeof score !== 'object' || Array.isArray(score)) return 'the body is not a score object';
    if (typeof score.userId !== 'string' || score.userId === '') return 'userId must be a non-empty string';
    if (score.scoreGiven !== undefined) {
        if (typeof score.scoreGiven !== 'number' || !(score.scoreGiven >= 0)) return 'scoreGiven must be a number >= 0';
        if (typeof score.scoreMaximum !== 'number' || !(score.scoreMaximum > 0))
            return 'scoreMaximum must be a number > 0 when scoreGiven is given';
    } else if (score.scoreMaximum !== undefined && (typeof score.scoreMaximum !== 'number' || !(score.scoreMaximum > 0)))
        return 'scoreMaximum must be a number > 0';
    if (!ACTIVITY_PROGRESS.has(score.activityProgress))
        return `activityProgress must be one of ${[...ACTIVITY_PROGRESS].join(', ')}`;
    if (!GRADING_PROGRESS.has(score.gradingProgress))
        return `gradingProgress must be one of ${[...GRADING_PROGRESS].join(', ')}`;
    if (typeof score.timestamp !== 'string' || !ISO_8601.test(score.timestamp) || Number.isNaN(Date.parse(score.timestamp)))
        return 'timestamp must be an ISO 8601 date and time with a zone';
    if (score.comment !== undefined && score.comment !== null && typeof score.comment !== 'string') return 'comment must be a string';
    return null;
}

async function postScore(platform, req, res, entry) {
    if (!authorize(platform, req, res, [SCOPES.score])) return;
    if (mediaType(req) !== MEDIA.score) return refuse(res, 415, 'unsupported_media_type', `Content-Type must be ${MEDIA.score}`);
    const score = parseJson(await readBody(req));
    const problem = scoreProblem(score);
    if (problem) return refuse(res, 400, 'invalid_request', problem);

    // §3.4.4: a result is never updated by a score older than the one on record; a repeated
    // timestamp is refused too, so a tool that resends is seen to.
    const previous = entry.results.get(score.userId);
    const at = Date.parse(score.timestamp);
    if (previous && at <= previous.at)
        return refuse(res, 409, 'conflict', `a score with timestamp ${previous.timestamp} is already on record for ${score.userId}`);

    const resultId = `${entry.item.id}/results/${encodeURIComponent(score.userId)}`;
    const result = {
        id: resultId, scoreOf: entry.item.id, userId: score.userId,
        // §3.4.3: a score without scoreGiven clears the result's score.
        ...(score.scoreGiven !== undefined && { resultScore: score.scoreGiven, resultMaximum: score.scoreMaximum }),
        ...(typeof score.comment === 'string' && { comment: score.comment }),
        timestamp: score.timestamp,
    };
    Object.defineProperty(result, 'at', { value: at, enumerable: false });  // for the ordering, not the JSON
    entry.results.set(score.userId, result);
    platform.scores.push({ lineitem: entry.item.id, receivedAt: new Date().toISOString(), score });
    res.note = `score for ${score.userId} on ${entry.item.id}`;
    res.writeHead(204).end();
}
