// A real OpenID provider for tlmhub's sign-in tests: npm's oidc-provider (a certified
// implementation) served over TLS on loopback. The test writes a JSON file and passes its path:
//   {"port", "certFile", "keyFile", "clients": [oidc-provider client metadata],
//    "accounts": {"<login>": {claims}}}
// The issuer is https://127.0.0.1:<port>. Sign-in uses oidc-provider's development pages (a
// login form taking any listed account, then consent). Prints "ready" once it listens.
import { generateKeyPairSync } from 'node:crypto';
import { readFileSync } from 'node:fs';
import https from 'node:https';
import Provider from 'oidc-provider';

const config = JSON.parse(readFileSync(process.argv[2], 'utf8'));
const issuer = `https://127.0.0.1:${config.port}`;

// A new RSA key at every start: a restarted provider has rotated its keys.
function signingKey(kid) {
    const { privateKey } = generateKeyPairSync('rsa', { modulusLength: 2048 });
    return { ...privateKey.export({ format: 'jwk' }), kid, alg: 'RS256', use: 'sig' };
}

const provider = new Provider(issuer, {
    clients: config.clients,
    jwks: { keys: [signingKey(`key-${Date.now()}`)] },
    cookies: { keys: ['tlmhub-test-cookie-key'] },
    claims: { openid: ['sub'], profile: ['name', 'preferred_username', 'groups'], email: ['email'] },
    conformIdTokenClaims: false,   // the profile claims in the ID token, as most providers put them
    pkce: { required: () => true },
    async findAccount(ctx, id) {
        const claims = config.accounts[id];
        if (!claims) return undefined;
        return { accountId: id, claims: async () => ({ sub: id, ...claims }) };
    },
});

https.createServer({ cert: readFileSync(config.certFile), key: readFileSync(config.keyFile) }, provider.callback())
    .listen(config.port, '127.0.0.1', () => console.log('ready'));
