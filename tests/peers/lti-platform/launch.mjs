// The message side of the platform: starting a launch (LTI 1.3 Core §4.1 and IMS Security
// Framework 1.0 §5.1.1: third-party initiated login), the OIDC authentication request that
// answers with the signed LTI message (§5.1.1.2–5.1.1.3), and the Deep Linking 2.0 response.
import { randomBytes } from 'node:crypto';
import { generateKeyPair, jwtVerify, SignJWT, UnsecuredJWT } from 'jose';
import { createLineItem, ensureContext, lineItemProblem, lineItemsUrl, SCOPES } from './ags.mjs';
import { autoPostPage, escapeHtml, parseForm, readBody, refuse, sendHtml, sendJson, simplePage, wantsJson } from './web.mjs';

const LTI = 'https://purl.imsglobal.org/spec/lti/claim/';
const LTI_DL = 'https://purl.imsglobal.org/spec/lti-dl/claim/';
const AGS_ENDPOINT = 'https://purl.imsglobal.org/spec/lti-ags/claim/endpoint';
const LAUNCH_LIFETIME_MS = 10 * 60 * 1000;
// Short claim names a tamper may use for the LTI claims (expanded to their full names).
const SHORT_CLAIMS = {
    ...Object.fromEntries(['message_type', 'version', 'deployment_id', 'target_link_uri', 'resource_link', 'roles',
        'context', 'tool_platform', 'launch_presentation', 'custom', 'lis', 'role_scope_mentor'].map((n) => [n, LTI + n])),
    deep_linking_settings: `${LTI_DL}deep_linking_settings`,
    endpoint: AGS_ENDPOINT,
};
const MESSAGE_TYPES = new Set(['LtiResourceLinkRequest', 'LtiDeepLinkingRequest']);

const token = () => randomBytes(12).toString('base64url');

// A role as the LIS vocabulary IRI (LTI 1.3 Core §5.3.7, appendix A.2); short names are context roles,
// except Administrator, which is an institution role.
function roleIri(role) {
    if (role.includes(':')) return role;
    if (role === 'Administrator') return 'http://purl.imsglobal.org/vocab/lis/v2/institution/person#Administrator';
    return `http://purl.imsglobal.org/vocab/lis/v2/membership#${role}`;
}

// POST /control/launch: remembers a launch and answers the tool's login initiation URL for it.
export async function controlLaunch(platform, body) {
    const { config } = platform;
    const messageType = body.messageType ?? 'LtiResourceLinkRequest';
    if (!MESSAGE_TYPES.has(messageType)) throw Object.assign(new Error(`unknown messageType ${messageType}`), { status: 400 });
    const user = { sub: 'user-1', name: 'Ada Lovelace', email: 'ada@example.org', roles: ['Learner'], ...body.user };
    const context = ensureContext(platform, { id: 'course-1', ...body.context });
    const launch = {
        loginHint: token(), messageHint: token(), created: Date.now(), messageType, user, context,
        custom: body.custom, tamper: body.tamper ?? {}, ags: body.ags === true, deepLinkingSettings: body.deepLinkingSettings,
    };
    if (messageType === 'LtiResourceLinkRequest') {
        const id = body.resourceLink?.id ?? `link-${platform.nextNumber()}`;
        const placed = platform.resourceLinks.get(id);  // a link placed by deep linking keeps what the tool gave it
        launch.resourceLink = { id, title: body.resourceLink?.title ?? placed?.title ?? 'Activity' };
        launch.targetLinkUri = body.targetLinkUri ?? placed?.url ?? config.tool.launchUrl;
        launch.custom ??= placed?.custom;
        launch.lineitem = placed?.lineitem;
        if (body.lineItem) {
            const problem = lineItemProblem({ label: launch.resourceLink.title, ...body.lineItem });
            if (problem) throw Object.assign(new Error(`lineItem: ${problem}`), { status: 400 });
            launch.lineitem = createLineItem(platform, context, { label: launch.resourceLink.title, ...body.lineItem, resourceLinkId: id }).id;
        }
    } else {
        launch.targetLinkUri = body.targetLinkUri ?? config.tool.launchUrl;
    }
    platform.launches.set(launch.loginHint, launch);

    const login = new URL(config.tool.loginUrl);
    login.searchParams.set('iss', platform.issuer);
    login.searchParams.set('login_hint', launch.loginHint);
    login.searchParams.set('target_link_uri', launch.targetLinkUri);
    login.searchParams.set('lti_message_hint', launch.messageHint);
    login.searchParams.set('client_id', config.clientId);
    login.searchParams.set('lti_deployment_id', config.deploymentId);
    return { loginUrl: login.href, lineitem: launch.lineitem ?? null };
}

// The LTI message of `launch` as id_token claims (LTI 1.3 Core §5.3–5.4, Deep Linking 2.0 §4.4).
function messageClaims(platform, launch, nonce) {
    const { config, issuer } = platform;
    const { user, context } = launch;
    const [givenName, ...rest] = (user.name ?? '').split(' ');
    const now = Math.floor(Date.now() / 1000);
    const claims = {
        iss: issuer, aud: config.clientId, azp: config.clientId, sub: user.sub, iat: now, exp: now + 300, nonce,
        name: user.name, given_name: givenName, family_name: rest.join(' '), email: user.email, locale: 'en-US',
        [`${LTI}message_type`]: launch.messageType,
        [`${LTI}version`]: '1.3.0',
        [`${LTI}deployment_id`]: config.deploymentId,
        [`${LTI}target_link_uri`]: launch.targetLinkUri,
        [`${LTI}roles`]: (user.roles ?? []).map(roleIri),
        [`${LTI}context`]: { id: context.id, label: context.label, title: context.title,
                             type: ['http://purl.imsglobal.org/vocab/lis/v2/course#CourseOffering'] },
        [`${LTI}tool_platform`]: { guid: `tlmhub-test-platform-${config.port}`, name: 'tlmhub test LTI platform',
                                   product_family_code: 'tlmhub-test-platform', version: '1.0' },
        [`${LTI}launch_presentation`]: { document_target: 'iframe', return_url: `${issuer}/launch-return`, locale: 'en-US' },
    };
    if (launch.custom) claims[`${LTI}custom`] = launch.custom;
    if (launch.resourceLink) claims[`${LTI}resource_link`] = launch.resourceLink;
    if (launch.lineitem || launch.ags) {
        claims[AGS_ENDPOINT] = { scope: Object.values(SCOPES), lineitems: lineItemsUrl(platform, context.id),
                                 ...(launch.lineitem && { lineitem: launch.lineitem }) };
    }
    if (launch.messageType === 'LtiDeepLinkingRequest') {
        const data = token();  // opaque; the response must carry it back (Deep Linking 2.0 §4.4.1)
        platform.deepLinkRequests.set(data, { launch, answered: false });
        claims[`${LTI_DL}deep_linking_settings`] = {
            deep_link_return_url: `${issuer}/deep-link-return`, accept_types: ['ltiResourceLink'],
            accept_presentation_document_targets: ['iframe', 'window'], accept_multiple: false, auto_create: true,
            ...launch.deepLinkingSettings, data,
        };
    }
    return claims;
}

// "+60"/"-600" as seconds from now for the time claims; any other value as is.
function tamperValue(name, value) {
    if (['iat', 'exp', 'nbf'].includes(name) && typeof value === 'string' && /^[+-]\d+$/.test(value))
        return Math.floor(Date.now() / 1000) + Number(value);
    return value;
}

// The id_token, signed with the current key unless the launch's tamper says otherwise.
async function signMessage(platform, launch, claims) {
    const tamper = launch.tamper;
    for (const [name, value] of Object.entries(tamper.claims ?? {})) {
        const full = SHORT_CLAIMS[name] ?? name;
        if (value === null) delete claims[full];
        else claims[full] = tamperValue(name, value);
    }
    if (tamper.alg === 'none') return new UnsecuredJWT(claims).encode();
    const current = platform.keys[0];
    let key = current.privateKey;
    if (tamper.signWith === 'unknownKey') {
        platform.strangerKey ??= (await generateKeyPair('RS256', { modulusLength: 2048 })).privateKey;
        key = platform.strangerKey;  // the header still names the current kid: only the signature is wrong
    }
    const header = { alg: 'RS256', typ: 'JWT', kid: current.kid };
    if ('kid' in tamper) {
        if (tamper.kid === null) delete header.kid;
        else header.kid = tamper.kid;
    }
    return new SignJWT(claims).setProtectedHeader(header).sign(key);
}

// GET or POST /auth: the OIDC authentication request of the launch (Security Framework §5.1.1.2).
export async function handleAuth(platform, req, res, url) {
    const params = req.method === 'POST' ? parseForm(await readBody(req)) : Object.fromEntries(url.searchParams);
    const { config } = platform;
    // RFC 6749 §4.1.2.1: with an unknown client or redirect URI nothing is sent to the redirect URI.
    if (params.client_id !== config.clientId)
        return refuse(res, 400, 'unauthorized_client', `unknown client_id ${params.client_id}`);
    if (params.redirect_uri !== config.tool.launchUrl)
        return refuse(res, 400, 'invalid_request', `redirect_uri ${params.redirect_uri} is not registered`);

    const launch = platform.launches.get(params.login_hint);
    const fault = (() => {
        if (!(params.scope ?? '').split(' ').includes('openid')) return ['invalid_scope', 'scope must contain openid'];
        if (params.response_type !== 'id_token') return ['unsupported_response_type', 'response_type must be id_token'];
        if (params.response_mode !== 'form_post') return ['invalid_request', 'response_mode must be form_post'];
        if (params.prompt !== 'none') return ['invalid_request', 'prompt must be none'];
        if (!params.state) return ['invalid_request', 'state is missing'];
        if (!params.nonce) return ['invalid_request', 'nonce is missing'];
        if (!launch || Date.now() - launch.created > LAUNCH_LIFETIME_MS)
            return ['login_required', 'login_hint names no pending launch'];
        if (params.lti_message_hint !== launch.messageHint)
            return ['invalid_request', 'lti_message_hint does not belong to login_hint'];
        return null;
    })();

    let fields;
    if (fault) {
        res.note = `${fault[0]}: ${fault[1]}`;
        fields = { error: fault[0], error_description: fault[1], ...(params.state && { state: params.state }) };
    } else {
        const idToken = await signMessage(platform, launch, messageClaims(platform, launch, params.nonce));
        res.note = `${launch.messageType} for ${launch.user.sub}`;
        fields = { id_token: idToken, state: launch.tamper.state ?? params.state };
    }
    if (wantsJson(req)) return sendJson(res, 200, { action: params.redirect_uri, ...fields });
    sendHtml(res, 200, autoPostPage(params.redirect_uri, fields));
}

// POST /deep-link-return: the tool's LtiDeepLinkingResponse (Deep Linking 2.0 §4.5).
export async function handleDeepLinkReturn(platform, req, res) {
    const { config, issuer } = platform;
    const answer = (status, error, description) => {
        res.note = `${error}: ${description}`;
        if (wantsJson(req)) return refuse(res, status, error, description);
        sendHtml(res, status, simplePage('Deep linking response refused', `<p>${escapeHtml(description)}</p>`));
    };
    const jwt = parseForm(await readBody(req)).JWT;
    if (!jwt) return answer(400, 'invalid_request', 'the form has no JWT field');
    let claims;
    try {
        ({ payload: claims } = await jwtVerify(jwt, platform.toolJwks, {
            issuer: config.clientId, audience: issuer, algorithms: ['RS256'], requiredClaims: ['exp', 'iat', 'nonce'],
            clockTolerance: 5,
        }));
    } catch (err) {
        return answer(400, 'invalid_request', `JWT refused: ${err.code ?? ''} ${err.message}`.trim());
    }
    if (claims[`${LTI}message_type`] !== 'LtiDeepLinkingResponse')
        return answer(400, 'invalid_request', 'message_type must be LtiDeepLinkingResponse');
    if (claims[`${LTI}version`] !== '1.3.0') return answer(400, 'invalid_request', 'version must be 1.3.0');
    if (claims[`${LTI}deployment_id`] !== config.deploymentId) return answer(400, 'invalid_request', 'deployment_id is not this deployment');
    const request = platform.deepLinkRequests.get(claims[`${LTI_DL}data`]);
    if (!request) return answer(400, 'invalid_request', 'data does not match any deep linking request');
    if (request.answered) return answer(400, 'invalid_request', 'that deep linking request was already answered');

    const items = claims[`${LTI_DL}content_items`] ?? [];
    const settings = { accept_multiple: false, ...request.launch.deepLinkingSettings };
    if (!Array.isArray(items)) return answer(400, 'invalid_request', 'content_items must be an array');
    if (items.length > 1 && !settings.accept_multiple) return answer(400, 'invalid_request', 'only one content item is accepted');
    for (const item of items) {
        if (item?.type !== 'ltiResourceLink') return answer(400, 'invalid_request', `content item type ${item?.type} is not accepted`);
        if (item.url !== undefined && typeof item.url !== 'string') return answer(400, 'invalid_request', 'url must be a string');
        if (item.lineItem !== undefined) {
            const problem = lineItemProblem({ label: item.title ?? 'Activity', ...item.lineItem });
            if (problem) return answer(400, 'invalid_request', `lineItem: ${problem}`);
        }
    }

    // auto_create: each link is placed in the course, with its gradebook column when it asks for one.
    request.answered = true;
    const context = request.launch.context;
    const placed = items.map((item) => {
        const resourceLinkId = `link-${platform.nextNumber()}`;
        const lineitem = item.lineItem
            ? createLineItem(platform, context, { label: item.title ?? 'Activity', ...item.lineItem, resourceLinkId }).id
            : undefined;
        const link = { resourceLinkId, contextId: context.id, url: item.url ?? config.tool.launchUrl, title: item.title,
                       custom: item.custom, lineitem, item };
        platform.resourceLinks.set(resourceLinkId, link);
        return link;
    });
    platform.deepLinks.push({ receivedAt: new Date().toISOString(), claims, placed });
    res.note = `placed ${placed.length} item(s)`;
    if (wantsJson(req)) return sendJson(res, 200, { placed });
    const list = placed.map((p) => `<li>${escapeHtml(p.title ?? p.url)} (${escapeHtml(p.resourceLinkId)})</li>`).join('');
    const message = claims[`${LTI_DL}msg`] ? `<p>${escapeHtml(claims[`${LTI_DL}msg`])}</p>` : '';
    sendHtml(res, 200, simplePage('Content placed', `${message}<ul>${list}</ul>`));
}
