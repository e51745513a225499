// OpenID Connect against a real provider (issue 43 item 1): npm's certified oidc-provider,
// started by the test over TLS on loopback. A browser's walk through its login and consent
// pages brings the code back; the server's side (discovery, the code exchanged with the PKCE
// verifier and the client's secret, the ID token checked against the provider's published
// keys) takes it, and refuses a used code, a wrong verifier or nonce, and a provider it
// cannot trust or reach.
#include "ServerHarness.h"
#include "TemporaryOidcProvider.h"

#include "server/auth/oidc/OidcProvider.h"

#include <gtest/gtest.h>

#include <ctime>

using namespace tlmhub::server;
using tlmhub::test::TemporaryOidcProvider;

namespace {

const std::string kRedirect = "http://127.0.0.1:9/api/v1/auth/oidc/uni/callback";

// A query parameter of `url`, percent-decoded; "" when absent.
std::string queryValue(const std::string& url, const std::string& name)
{
    const std::size_t query = url.find('?');
    if (query == std::string::npos) return {};
    std::size_t at = query;
    while (at != std::string::npos) {
        const std::size_t start = at + 1;
        const std::size_t end = url.find('&', start);
        const std::string pair = url.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (pair.starts_with(name + "=")) {
            std::string value;
            for (std::size_t i = name.size() + 1; i < pair.size(); ++i)
                if (pair[i] == '%' && i + 2 < pair.size()) {
                    value += static_cast<char>(std::stoi(pair.substr(i + 1, 2), nullptr, 16));
                    i += 2;
                } else {
                    value += pair[i];
                }
            return value;
        }
        at = end;
    }
    return {};
}

std::string refusal(const std::variant<IdToken, IdTokenError>& outcome)
{
    return std::holds_alternative<IdTokenError>(outcome) ? std::get<IdTokenError>(outcome).code : "";
}

class OidcProviderPeer : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        peer = new TemporaryOidcProvider({kRedirect}, {{"jane", R"({"name": "Jane Doe", "groups": ["teachers"]})"}});
    }
    static void TearDownTestSuite()
    {
        delete peer;
        peer = nullptr;
    }

    OidcProviderSettings settings() const
    {
        return {"uni", "University", peer->issuer(), TemporaryOidcProvider::kClientId,
                TemporaryOidcProvider::kClientSecret};
    }
    // A sign-in walked to the provider's answer: the callback address.
    std::string signIn(OidcProvider& provider, const SignInSecrets& secrets)
    {
        std::string error;
        const auto url = provider.authorizationUrl(secrets, kRedirect, error);
        if (!url) throw std::runtime_error("no authorization address: " + error);
        return peer->signInThroughBrowser(*url, "jane");
    }

    static TemporaryOidcProvider* peer;
    ProviderHttp http{peer->caFile()};
};
TemporaryOidcProvider* OidcProviderPeer::peer = nullptr;

} // namespace

TEST_F(OidcProviderPeer, ASignInEndsInAnIdTokenCheckedAgainstTheProvidersKeys)
{
    OidcProvider provider(settings(), http);
    const SignInSecrets secrets = newSignInSecrets();
    const std::string callback = signIn(provider, secrets);
    ASSERT_TRUE(callback.starts_with(kRedirect + "?")) << callback;
    EXPECT_EQ(queryValue(callback, "state"), secrets.state);
    EXPECT_EQ(queryValue(callback, "iss"), peer->issuer());
    const auto outcome =
        provider.finish(queryValue(callback, "code"), secrets.codeVerifier, secrets.nonce, kRedirect, std::time(nullptr));
    ASSERT_EQ(refusal(outcome), "") << std::get<IdTokenError>(outcome).message << "\n" << peer->logTail();
    const IdToken& token = std::get<IdToken>(outcome);
    EXPECT_EQ(token.subject, "jane");
    EXPECT_EQ(token.claims.at("name"), "Jane Doe");
    EXPECT_EQ(token.claims.at("groups"), nlohmann::json::array({"teachers"}));
}

TEST_F(OidcProviderPeer, ACodeIsTakenOnceAndOnlyWithItsVerifierAndItsNonce)
{
    OidcProvider provider(settings(), http);
    const std::time_t now = std::time(nullptr);
    const SignInSecrets first = newSignInSecrets();
    const std::string code = queryValue(signIn(provider, first), "code");
    ASSERT_EQ(refusal(provider.finish(code, first.codeVerifier, first.nonce, kRedirect, now)), "");
    EXPECT_EQ(refusal(provider.finish(code, first.codeVerifier, first.nonce, kRedirect, now)), "token_refused")
        << "a code is used once";

    const SignInSecrets second = newSignInSecrets();
    const std::string secondCode = queryValue(signIn(provider, second), "code");
    EXPECT_EQ(refusal(provider.finish(secondCode, first.codeVerifier, second.nonce, kRedirect, now)), "token_refused")
        << "another sign-in's verifier (PKCE)";

    const SignInSecrets third = newSignInSecrets();
    const std::string thirdCode = queryValue(signIn(provider, third), "code");
    EXPECT_EQ(refusal(provider.finish(thirdCode, third.codeVerifier, first.nonce, kRedirect, now)), "wrong_nonce")
        << "a token for another sign-in";
}

TEST_F(OidcProviderPeer, AProviderOfAnotherCaOrUnreachableCannotBeAskedAndSaysWhy)
{
    const ProviderHttp otherCa{peer->otherCaFile()};
    OidcProvider untrusted(settings(), otherCa);
    std::string error;
    EXPECT_FALSE(untrusted.authorizationUrl(newSignInSecrets(), kRedirect, error));
    EXPECT_NE(error.find("certificate"), std::string::npos) << error;

    OidcProviderSettings gone = settings();
    gone.issuer = "https://127.0.0.1:" + std::to_string(tlmhub::test::freeLoopbackPort());
    OidcProvider unreachable(gone, http);
    EXPECT_FALSE(unreachable.authorizationUrl(newSignInSecrets(), kRedirect, error));
    EXPECT_NE(error.find("cannot connect"), std::string::npos) << error;
    const auto finished = unreachable.finish("code", "verifier", "nonce", kRedirect, std::time(nullptr));
    EXPECT_EQ(refusal(finished), "provider_unavailable");
}
