// The start of an OpenID Connect sign-in (issue 43 item 1): the provider's discovery document
// taken only when it can do what the server asks, and the address the browser is sent to,
// with fresh state, nonce and PKCE challenge (RFC 7636's own example checks the challenge).
#include "server/auth/oidc/AuthorizationRequest.h"
#include "server/auth/oidc/ProviderMetadata.h"

#include <gtest/gtest.h>

#include <set>

using namespace tlmhub::server;

namespace {

const std::string kStartIssuer = "https://login.example.edu/realms/staff";

nlohmann::json keycloakLikeDocument()
{
    return {{"issuer", kStartIssuer},
            {"authorization_endpoint", kStartIssuer + "/protocol/openid-connect/auth"},
            {"token_endpoint", kStartIssuer + "/protocol/openid-connect/token"},
            {"jwks_uri", kStartIssuer + "/protocol/openid-connect/certs"},
            {"response_types_supported", {"code", "id_token", "code id_token"}},
            {"id_token_signing_alg_values_supported", {"PS384", "ES384", "RS256", "HS256"}},
            {"code_challenge_methods_supported", {"plain", "S256"}},
            {"token_endpoint_auth_methods_supported", {"private_key_jwt", "client_secret_basic", "client_secret_post"}}};
}

std::string refusal(const nlohmann::json& document)
{
    std::string error;
    return parseProviderMetadata(document, kStartIssuer, error) ? std::string{} : error;
}

} // namespace

TEST(OidcSignInStart, ADiscoveryDocumentIsTakenOnlyForTheIssuerAndWhatTheServerAsks)
{
    std::string error;
    const auto metadata = parseProviderMetadata(keycloakLikeDocument(), kStartIssuer, error);
    ASSERT_TRUE(metadata) << error;
    EXPECT_EQ(metadata->tokenEndpoint, kStartIssuer + "/protocol/openid-connect/token");
    EXPECT_EQ(metadata->tokenAuthMethod, "client_secret_basic");
    EXPECT_EQ(discoveryUrl(kStartIssuer), kStartIssuer + "/.well-known/openid-configuration");
    EXPECT_EQ(discoveryUrl("https://accounts.example.com/"), "https://accounts.example.com/.well-known/openid-configuration");

    struct Case {
        const char* what;
        nlohmann::json change;
        const char* named;   // in the error
    };
    const std::vector<Case> cases = {
        {"another issuer", {{"issuer", "https://evil.example.com"}}, "another issuer"},
        {"the issuer with a slash more", {{"issuer", kStartIssuer + "/"}}, "another issuer"},
        {"plain http", {{"token_endpoint", "http://login.example.edu/token"}}, "token_endpoint"},
        {"credentials in the address", {{"authorization_endpoint", "https://user:pw@login.example.edu/auth"}},
         "authorization_endpoint"},
        {"no key set", {{"jwks_uri", nullptr}}, "jwks_uri"},
        {"no code flow", {{"response_types_supported", {"id_token"}}}, "authorization code"},
        {"PKCE plain only", {{"code_challenge_methods_supported", {"plain"}}}, "S256"},
        {"HMAC-signed ID tokens only", {{"id_token_signing_alg_values_supported", {"HS256", "none"}}}, "algorithm"},
        {"no secret methods", {{"token_endpoint_auth_methods_supported", {"private_key_jwt"}}}, "client_secret"},
    };
    for (const Case& c : cases) {
        nlohmann::json document = keycloakLikeDocument();
        document.merge_patch(c.change);
        EXPECT_NE(refusal(document).find(c.named), std::string::npos) << c.what << ": " << refusal(document);
    }
    // Left out, the specification's defaults hold: S256 assumed, RS256, client_secret_basic.
    nlohmann::json minimal = keycloakLikeDocument();
    minimal.merge_patch({{"code_challenge_methods_supported", nullptr},
                         {"id_token_signing_alg_values_supported", nullptr},
                         {"token_endpoint_auth_methods_supported", nullptr}});
    EXPECT_EQ(refusal(minimal), "");
    nlohmann::json postOnly = keycloakLikeDocument();
    postOnly["token_endpoint_auth_methods_supported"] = {"client_secret_post"};
    EXPECT_EQ(parseProviderMetadata(postOnly, kStartIssuer, error)->tokenAuthMethod, "client_secret_post");
    EXPECT_NE(refusal(nlohmann::json::array()).find("not a JSON object"), std::string::npos);
}

TEST(OidcSignInStart, TheBrowserIsSentWithFreshSecretsAndTheS256Challenge)
{
    // RFC 7636, Appendix B
    EXPECT_EQ(pkceChallenge("dBjftJeZ4CVP-mB92K27uhbUJU1p1r_wW1gFWFOEjXk"), "E9Melhoa2OwvFrEMTJguCHaoeK1t8URWbuGJSstw-cM");

    std::set<std::string> seen;
    for (int i = 0; i < 20; ++i) {
        const SignInSecrets secrets = newSignInSecrets();
        for (const std::string* secret : {&secrets.state, &secrets.nonce, &secrets.codeVerifier}) {
            EXPECT_EQ(secret->size(), 43U) << "32 bytes, base64url";
            EXPECT_TRUE(seen.insert(*secret).second) << "never the same twice";
        }
    }

    ProviderMetadata provider;
    provider.authorizationEndpoint = "https://login.example.edu/auth?tenant=staff";
    const SignInSecrets secrets{"the-state", "the-nonce", "dBjftJeZ4CVP-mB92K27uhbUJU1p1r_wW1gFWFOEjXk"};
    EXPECT_EQ(authorizationUrl(provider, "tlmhub lab", "https://tlmhub.example.edu/api/v1/auth/oidc/uni/callback", secrets),
              "https://login.example.edu/auth?tenant=staff&response_type=code&client_id=tlmhub%20lab"
              "&redirect_uri=https%3A%2F%2Ftlmhub.example.edu%2Fapi%2Fv1%2Fauth%2Foidc%2Funi%2Fcallback"
              "&scope=openid%20profile%20email&state=the-state&nonce=the-nonce"
              "&code_challenge=E9Melhoa2OwvFrEMTJguCHaoeK1t8URWbuGJSstw-cM&code_challenge_method=S256");
    EXPECT_EQ(formEncode({{"a b", "x&y=z/é~"}}), "a%20b=x%26y%3Dz%2F%C3%A9~");
}
