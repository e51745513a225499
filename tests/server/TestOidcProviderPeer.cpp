// OpenID Connect against a real provider (issue 43 item 1): npm's certified oidc-provider,
// started by the test over TLS on loopback. A browser's walk through its login and consent
// pages brings the code back; the server's side (discovery, the code exchanged with the PKCE
// verifier and the client's secret, the ID token checked against the provider's published
// keys) takes it, and refuses a used code, a wrong verifier or nonce, and a provider it
// cannot trust or reach. Through a running server: the start's redirect, the callback's
// one-time hand-over to the app, the person's own account (never a local one by name), the
// role from the groups claim, and answers replayed or made up.
#include "ServerHarness.h"
#include "TemporaryOidcProvider.h"

#include "server/auth/oidc/OidcProvider.h"
#include "server/http/Router.h"

#include <gtest/gtest.h>

#include <ctime>
#include <filesystem>
#include <fstream>

using namespace tlmhub::server;
using tlmhub::test::TemporaryOidcProvider;

namespace {

const std::string kRedirect = "http://127.0.0.1:9/api/v1/auth/oidc/uni/callback";

// A query parameter of `url`, percent-decoded; "" when absent.
std::string queryValue(const std::string& url, const std::string& name)
{
    const std::size_t query = url.find('?');
    if (query == std::string::npos) return {};
    const auto params = tlmhub::server::parseRequestTarget(url.substr(query)).query;
    const auto it = params.find(name);
    return it == params.end() ? std::string{} : it->second;
}

std::string peerRefusal(const std::variant<IdToken, IdTokenError>& outcome)
{
    return std::holds_alternative<IdTokenError>(outcome) ? std::get<IdTokenError>(outcome).code : "";
}

class OidcProviderPeer : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        serverPort = tlmhub::test::freeLoopbackPort();
        peer = new TemporaryOidcProvider({kRedirect, serverUrl() + "/api/v1/auth/oidc/university/callback"},
                                         {{"jane", R"({"name": "Jane Doe", "groups": ["teachers"]})"},
                                          {"admin", R"({"preferred_username": "admin"})"}});
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

    static std::string serverUrl() { return "http://127.0.0.1:" + std::to_string(serverPort); }

    // A server signing in through the peer as "University", teachers' group mapped.
    std::unique_ptr<tlmhub::test::ServerProcess> server(const std::string& name, std::vector<std::string> more = {})
    {
        const auto dir = tlmhub::test::freshTempDir(name);
        const auto secret = dir.parent_path() / (name + "-client-secret");
        std::ofstream(secret) << TemporaryOidcProvider::kClientSecret << "\n";
        std::filesystem::permissions(secret, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
        std::vector<std::string> args = {"--listen", "127.0.0.1:" + std::to_string(serverPort), "--public-url", serverUrl(),
                                         "--oidc-issuer", peer->issuer(), "--oidc-client-id", TemporaryOidcProvider::kClientId,
                                         "--oidc-client-secret-file", secret.string(), "--oidc-name", "University",
                                         "--oidc-role", "teacher=teachers", "--oidc-ca-file", peer->caFile().string()};
        args.insert(args.end(), more.begin(), more.end());
        return std::make_unique<tlmhub::test::ServerProcess>(dir, args);
    }
    // A browser at the server: the start, keeping its sign-in cookie; returns the provider's address.
    static std::string startIn(tlmhub::test::HttpClient& browser)
    {
        const auto started = browser.get("/api/v1/auth/oidc/university/start");
        if (started.status != 302) throw std::runtime_error("start: " + std::to_string(started.status) + " " + started.body);
        const std::string cookie = started.headers.at("Set-Cookie");
        browser.addHeader("Cookie", cookie.substr(0, cookie.find(';')));
        return started.headers.at("Location");
    }
    // The start, the provider's pages, the callback: where the server sends the browser back to.
    std::string signInThroughServer(const tlmhub::test::ServerProcess& server, const std::string& login)
    {
        tlmhub::test::HttpClient client(server.port());
        const std::string callback = peer->signInThroughBrowser(startIn(client), login);
        const auto back = client.get(callback.substr(serverUrl().size()));
        if (back.status != 303) throw std::runtime_error("callback: " + std::to_string(back.status) + " " + back.body);
        return back.headers.at("Location");
    }

    static TemporaryOidcProvider* peer;
    static unsigned short serverPort;
    ProviderHttp http{peer->caFile()};
};
TemporaryOidcProvider* OidcProviderPeer::peer = nullptr;
unsigned short OidcProviderPeer::serverPort = 0;

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
    ASSERT_EQ(peerRefusal(outcome), "") << std::get<IdTokenError>(outcome).message << "\n" << peer->logTail();
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
    ASSERT_EQ(peerRefusal(provider.finish(code, first.codeVerifier, first.nonce, kRedirect, now)), "");
    EXPECT_EQ(peerRefusal(provider.finish(code, first.codeVerifier, first.nonce, kRedirect, now)), "token_refused")
        << "a code is used once";

    const SignInSecrets second = newSignInSecrets();
    const std::string secondCode = queryValue(signIn(provider, second), "code");
    EXPECT_EQ(peerRefusal(provider.finish(secondCode, first.codeVerifier, second.nonce, kRedirect, now)), "token_refused")
        << "another sign-in's verifier (PKCE)";

    const SignInSecrets third = newSignInSecrets();
    const std::string thirdCode = queryValue(signIn(provider, third), "code");
    EXPECT_EQ(peerRefusal(provider.finish(thirdCode, third.codeVerifier, first.nonce, kRedirect, now)), "wrong_nonce")
        << "a token for another sign-in";
}

TEST_F(OidcProviderPeer, AnExpiredTokenIsRefusedAndARestartedProvidersNewKeyIsFetched)
{
    OidcProvider provider(settings(), http);
    const SignInSecrets late = newSignInSecrets();
    const std::string lateCode = queryValue(signIn(provider, late), "code");
    EXPECT_EQ(peerRefusal(provider.finish(lateCode, late.codeVerifier, late.nonce, kRedirect, std::time(nullptr) + 7200)),
              "expired")
        << "taken two hours later, past its exp";

    const SignInSecrets before = newSignInSecrets();
    ASSERT_EQ(peerRefusal(provider.finish(queryValue(signIn(provider, before), "code"), before.codeVerifier, before.nonce,
                                          kRedirect, std::time(nullptr))),
              "");
    peer->restart();   // a new signing key; the provider object still holds the old key set
    const SignInSecrets after = newSignInSecrets();
    const auto rotated = provider.finish(queryValue(signIn(provider, after), "code"), after.codeVerifier, after.nonce,
                                         kRedirect, std::time(nullptr));
    EXPECT_EQ(peerRefusal(rotated), "") << "the rotated key fetched at once: "
                                        << (std::holds_alternative<IdTokenError>(rotated) ? std::get<IdTokenError>(rotated).message : "");
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
    EXPECT_EQ(peerRefusal(finished), "provider_unavailable");
}

TEST_F(OidcProviderPeer, ThroughTheServerAPersonGetsTheirOwnAccountWithTheRoleOfTheirGroup)
{
    const auto running = server("oidc-server");
    tlmhub::test::HttpClient client(running->port());
    const auto listed = client.get("/api/v1/auth/providers").json();
    EXPECT_EQ(listed["providers"], nlohmann::json::parse(R"([{"name": "university", "display_name": "University"}])"));
    EXPECT_EQ(listed["password_login"], true);

    const std::string back = signInThroughServer(*running, "jane");
    const std::string prefix = serverUrl() + "/#/signed-in/";
    ASSERT_TRUE(back.starts_with(prefix)) << back;
    const std::string key = back.substr(prefix.size());
    const auto collected = client.post("/api/v1/auth/oidc/collect", {{"key", key}});
    ASSERT_EQ(collected.status, 200) << collected.body;
    EXPECT_EQ(collected.json()["user"]["username"], "Jane_Doe");
    EXPECT_EQ(collected.json()["user"]["role"], "teacher") << "her groups claim holds teachers";
    EXPECT_EQ(client.post("/api/v1/auth/oidc/collect", {{"key", key}}).status, 401) << "a key is collected once";
    tlmhub::test::HttpClient jane(running->port());
    jane.setToken(collected.json()["token"].get<std::string>());
    EXPECT_EQ(jane.get("/api/v1/auth/me").json()["username"], "Jane_Doe");

    // The same person again: the same account, not a second one.
    const std::string again = signInThroughServer(*running, "jane");
    const auto second = client.post("/api/v1/auth/oidc/collect", {{"key", again.substr(prefix.size())}});
    EXPECT_EQ(second.json()["user"]["id"], collected.json()["user"]["id"]);
    // A provider's "admin" is not the local administrator.
    const std::string admin = signInThroughServer(*running, "admin");
    const auto theirs = client.post("/api/v1/auth/oidc/collect", {{"key", admin.substr(prefix.size())}});
    EXPECT_EQ(theirs.json()["user"]["username"], "admin-2");
    EXPECT_EQ(theirs.json()["user"]["role"], "user");
}

TEST_F(OidcProviderPeer, ReplayedMadeUpOrRefusedAnswersSendTheBrowserBackWithTheReason)
{
    // A second provider that cannot be reached.
    const auto secret = tlmhub::test::freshTempDir("oidc-down-secret") / "secret";
    std::ofstream(secret) << "secret\n";
    std::filesystem::permissions(secret, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    const auto running = server("oidc-replay", {"--oidc-create-accounts", "off", "--oidc-issuer",
                                                "https://127.0.0.1:" + std::to_string(tlmhub::test::freeLoopbackPort()),
                                                "--oidc-client-id", "tlmhub", "--oidc-client-secret-file", secret.string(),
                                                "--oidc-name", "Down"});
    tlmhub::test::HttpClient client(running->port());
    const std::string failed = serverUrl() + "/#/sign-in-failed/";
    // Someone signs in and sends the answer on to another browser (a login CSRF): refused there.
    tlmhub::test::HttpClient attacker(running->port());
    const std::string pushed = peer->signInThroughBrowser(startIn(attacker), "jane");
    tlmhub::test::HttpClient victim(running->port());
    EXPECT_EQ(victim.get(pushed.substr(serverUrl().size())).headers.at("Location"), failed + "sign_in_failed");

    const std::string callback = peer->signInThroughBrowser(startIn(client), "jane");
    EXPECT_EQ(client.get(callback.substr(serverUrl().size())).headers.at("Location"), failed + "no_account")
        << "account making is off";
    EXPECT_EQ(client.get(callback.substr(serverUrl().size())).headers.at("Location"), failed + "sign_in_failed")
        << "the same answer twice";
    EXPECT_EQ(client.get("/api/v1/auth/oidc/university/callback?code=made-up&state=made-up").headers.at("Location"),
              failed + "sign_in_failed");
    // The provider's own refusal (the person cancelled) uses up the sign-in too.
    tlmhub::test::HttpClient cancelling(running->port());
    const std::string state = queryValue(startIn(cancelling), "state");
    EXPECT_EQ(cancelling.get("/api/v1/auth/oidc/university/callback?error=access_denied&state=" + state)
                  .headers.at("Location"),
              failed + "sign_in_failed");
    EXPECT_EQ(client.get("/api/v1/auth/oidc/nowhere/start").status, 404);
    const auto down = client.get("/api/v1/auth/oidc/down/start");
    EXPECT_EQ(down.status, 303) << down.body;
    EXPECT_EQ(down.headers.at("Location"), failed + "provider_unavailable") << "the browser goes back to the login page";
    EXPECT_EQ(client.post("/api/v1/auth/login", {{"username", "admin"}, {"password", tlmhub::test::kAdminPassword}}).status, 200)
        << "local logins are not affected";
    EXPECT_EQ(client.post("/api/v1/auth/oidc/collect", {{"key", "made-up"}}).status, 401);
    // An answer naming another issuer came from another provider (RFC 9207's mix-up).
    tlmhub::test::HttpClient mixedUp(running->port());
    const std::string mixedState = queryValue(startIn(mixedUp), "state");
    EXPECT_EQ(mixedUp.get("/api/v1/auth/oidc/university/callback?code=x&iss=https%3A%2F%2Fevil.example.com&state=" +
                          mixedState).headers.at("Location"),
              failed + "sign_in_failed");
    // Each refusal's details are in the server's log, and only there.
    running->terminate();
    for (const char* logged : {"another browser", "(no_account)", "has expired or was used",
                               "the provider answered access_denied", "another provider", "(provider_unavailable)"})
        EXPECT_NE(running->output().find(logged), std::string::npos) << logged << "\n" << running->output();
}
