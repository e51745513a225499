// Personal API tokens end to end (docs/studies.md, "API tokens"): created and shown once,
// used as a Bearer token on REST and on the WebSocket upgrade (never in the URL), revoked,
// expired and refused with their account, and limited per user.
#include "ServerHarness.h"

#include "core/Sha256.h"
#include "server/store/Storage.h"
#include "server/store/UnixTime.h"

#include <boost/system/system_error.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <regex>

namespace tlmhub::test {
namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace fs = std::filesystem;

// Whether the server closes `ws` within a second.
bool closesWithinASecond(WsClient& ws)
{
    const auto start = std::chrono::steady_clock::now();
    while (!ws.receive(1500).is_null()) {}
    return ws.closedByServer() && std::chrono::steady_clock::now() - start < std::chrono::seconds(1);
}

bool pings(WsClient& ws) { return ws.call("ping").value("ok", false); }

// One server for every test; each test has users of its own where it counts tokens or
// disables an account.
class ApiTokens : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dataDir = new fs::path(freshTempDir("apitokens"));
        server = new ServerProcess(*dataDir);
        createTestUsers(*server, {"alice", "bob", "dora", "erin", "fred", "gwen"});
    }
    static void TearDownTestSuite()
    {
        delete server;
        fs::remove_all(*dataDir);
        delete dataDir;
    }
    unsigned short port() const { return server->port(); }
    HttpClient as(const std::string& user) { return loggedInAs(*server, user); }
    HttpClient withToken(const std::string& token)
    {
        HttpClient c(port());
        c.setToken(token);
        return c;
    }
    static HttpReply create(HttpClient c, const nlohmann::json& body) { return c.post("/api/v1/tokens", body); }
    // A new token of `c`'s user; fails the test when refused.
    static std::pair<std::int64_t, std::string> newToken(HttpClient& c, const std::string& name = "script")
    {
        const HttpReply r = create(c, {{"name", name}});
        EXPECT_EQ(r.status, 201) << r.body;
        const auto json = r.json();
        return {json.value("id", std::int64_t{0}), json.value("token", std::string())};
    }
    // The caller's tokens as GET /tokens lists them.
    static nlohmann::json tokensOf(HttpClient c) { return c.get("/api/v1/tokens").json()["tokens"]; }
    static HttpReply revoke(HttpClient c, std::int64_t id)
    {
        return c.request(http::verb::delete_, "/api/v1/tokens/" + std::to_string(id));
    }

    static fs::path* dataDir;
    static ServerProcess* server;
};
fs::path* ApiTokens::dataDir = nullptr;
ServerProcess* ApiTokens::server = nullptr;

TEST_F(ApiTokens, ATokenIsShownOnceWhenCreatedAndNeverListed)
{
    HttpClient alice = as("alice");
    const long long before = server::unixNow();
    const HttpReply created = create(alice, {{"name", "nightly sweep"}});
    ASSERT_EQ(created.status, 201) << created.body;
    const auto token = created.json();
    const std::string text = token["token"].get<std::string>();
    EXPECT_TRUE(std::regex_match(text, std::regex("tlmh_[A-Za-z0-9_-]{43}"))) << text;
    EXPECT_EQ(token["name"], "nightly sweep");
    EXPECT_GE(token["created_at"].get<long long>(), before);
    EXPECT_TRUE(token["expires_at"].is_null()) << "no expires_in_days: lasts until deleted";
    EXPECT_TRUE(token["last_used_at"].is_null());

    const HttpReply listed = alice.get("/api/v1/tokens");
    ASSERT_EQ(listed.status, 200);
    EXPECT_EQ(listed.body.find(text), std::string::npos) << "the list shows the token's text";
    EXPECT_EQ(listed.body.find(text.substr(5, 20)), std::string::npos);
    const auto tokens = listed.json()["tokens"];
    ASSERT_FALSE(tokens.empty());
    EXPECT_EQ(tokens[0]["id"], token["id"]) << "newest first";
    EXPECT_EQ(tokens[0]["name"], "nightly sweep");
    EXPECT_FALSE(tokens[0].contains("token"));

    const HttpReply expiring = create(alice, {{"name", "for a month"}, {"expires_in_days", 30}});
    ASSERT_EQ(expiring.status, 201) << expiring.body;
    EXPECT_EQ(expiring.json()["expires_at"].get<long long>(), expiring.json()["created_at"].get<long long>() + 30 * 86400);
    EXPECT_NE(expiring.json()["token"], text) << "two tokens, one text";
}

TEST_F(ApiTokens, ABearerTokenWorksOnRestAndRecordsItsUse)
{
    HttpClient alice = as("alice");
    const auto [id, token] = newToken(alice);
    HttpClient script = withToken(token);
    const HttpReply me = script.get("/api/v1/auth/me");
    ASSERT_EQ(me.status, 200) << me.body;
    EXPECT_EQ(me.json()["username"], "alice");
    EXPECT_EQ(script.get("/api/v1/jobs").status, 200);
    for (const auto& t : tokensOf(alice)) {
        if (t["id"] == id) {
            EXPECT_FALSE(t["last_used_at"].is_null()) << "its use is not recorded";
        }
    }
    // A token that looks like one but was never issued.
    EXPECT_EQ(withToken("tlmh_" + std::string(43, 'A')).get("/api/v1/auth/me").status, 401);
    EXPECT_EQ(withToken(token + "x").get("/api/v1/auth/me").status, 401);
}

TEST_F(ApiTokens, ABearerTokenOpensAWebSocketInTheUpgradeHeader)
{
    HttpClient alice = as("alice");
    const auto [id, token] = newToken(alice);
    WsClient ws(port(), token, 0, WsToken::InHeader);
    EXPECT_TRUE(pings(ws));
    EXPECT_TRUE(websocketUpgradeDeclined(port(), "tlmh_" + std::string(43, 'B'), WsToken::InHeader));
}

TEST_F(ApiTokens, ATokenInTheUrlIsRefused)
{
    HttpClient alice = as("alice");
    const auto [id, token] = newToken(alice);
    EXPECT_THROW(WsClient(port(), token), boost::system::system_error) << "/ws?token= took an API token";
    // A login token still opens a WebSocket there (browsers cannot set the header).
    WsClient browser(port(), alice.login("alice", testPassword("alice")));
    EXPECT_EQ(browser.call("ping")["ok"], true);
}

TEST_F(ApiTokens, ARevokedTokenIsRefusedAtOnceAndItsWebSocketEnds)
{
    HttpClient alice = as("alice");
    const auto [id, token] = newToken(alice, "leaked");
    const auto [otherId, other] = newToken(alice, "kept");
    WsClient ws(port(), token, 0, WsToken::InHeader);
    WsClient otherWs(port(), other, 0, WsToken::InHeader);
    ASSERT_TRUE(pings(ws));
    ASSERT_EQ(withToken(token).get("/api/v1/auth/me").status, 200);

    EXPECT_EQ(revoke(alice, id).status, 204);
    EXPECT_EQ(withToken(token).get("/api/v1/auth/me").status, 401);
    EXPECT_TRUE(closesWithinASecond(ws)) << "the socket of the revoked token stays open";
    EXPECT_TRUE(pings(otherWs)) << "another token of the same user is not affected";
    EXPECT_EQ(withToken(other).get("/api/v1/auth/me").status, 200);
    for (const auto& t : tokensOf(alice)) EXPECT_NE(t["id"], id);
    EXPECT_EQ(revoke(alice, id).status, 404) << "revoked already";
}

TEST_F(ApiTokens, AnExpiredTokenIsRefused)
{
    HttpClient alice = as("alice");
    const auto aliceId = alice.get("/api/v1/auth/me").json()["id"].get<std::int64_t>();
    // Stored past the server, as it would be after its days ran out (SQLite allows a second
    // connection to the running server's file).
    const std::string token = "tlmh_" + std::string(42, 'e') + "1";
    Sha256 sha;
    sha.update(token);
    const auto now = static_cast<std::int64_t>(server::unixNow());
    {
        const auto storage = server::openStorage({.database = (*dataDir / "tlmhub.sqlite").string()});
        ASSERT_TRUE(storage->apiTokens().insert(aliceId, "expired", sha.hexDigest(), now - 86400, now - 1));
    }
    EXPECT_EQ(withToken(token).get("/api/v1/auth/me").status, 401);
    EXPECT_TRUE(websocketUpgradeDeclined(port(), token, WsToken::InHeader));
    bool listed = false;
    for (const auto& t : tokensOf(alice))
        if (t["name"] == "expired") listed = t["expires_at"] == now - 1;
    EXPECT_TRUE(listed) << "an expired token stays listed until it is deleted";
}

TEST_F(ApiTokens, AnotherUserCanNeitherListNorDeleteIt)
{
    HttpClient alice = as("alice");
    HttpClient bob = as("bob");
    const auto [id, token] = newToken(alice, "alice's");
    for (const auto& t : tokensOf(bob)) EXPECT_NE(t["id"], id);
    const HttpReply stolen = revoke(bob, id);
    EXPECT_EQ(stolen.status, 404) << stolen.body;
    EXPECT_EQ(withToken(token).get("/api/v1/auth/me").status, 200) << "bob revoked alice's token";
    // Neither can an administrator through this route: the tokens are the caller's own.
    EXPECT_EQ(revoke(as("admin"), id).status, 404);
    EXPECT_EQ(alice.request(http::verb::delete_, "/api/v1/tokens/not-a-number").status, 404);
    EXPECT_EQ(HttpClient(port()).get("/api/v1/tokens").status, 401);
}

TEST_F(ApiTokens, ADisabledAccountsTokensAreRefused)
{
    HttpClient erin = as("erin");
    const auto [id, token] = newToken(erin);
    WsClient ws(port(), token, 0, WsToken::InHeader);
    HttpClient admin = as("admin");
    const auto erinId = erin.get("/api/v1/auth/me").json()["id"].get<std::int64_t>();
    ASSERT_EQ(admin.request(http::verb::patch, "/api/v1/users/" + std::to_string(erinId), R"({"disabled": true})").status,
              200);
    EXPECT_EQ(withToken(token).get("/api/v1/auth/me").status, 401);
    EXPECT_TRUE(websocketUpgradeDeclined(port(), token, WsToken::InHeader));
    EXPECT_TRUE(closesWithinASecond(ws));
}

// Issue 37 L3: disabling and enabling again revived the tokens; disabling revokes them.
TEST_F(ApiTokens, EnablingADisabledAccountAgainRevivesNoToken)
{
    HttpClient gwen = as("gwen");
    const auto [id, token] = newToken(gwen);
    ASSERT_EQ(withToken(token).get("/api/v1/auth/me").status, 200);
    const auto gwenPath = "/api/v1/users/" + std::to_string(gwen.get("/api/v1/auth/me").json()["id"].get<std::int64_t>());
    HttpClient admin = as("admin");
    ASSERT_EQ(admin.request(http::verb::patch, gwenPath, R"({"disabled": true})").status, 200);
    ASSERT_EQ(admin.request(http::verb::patch, gwenPath, R"({"disabled": false})").status, 200);
    EXPECT_EQ(withToken(token).get("/api/v1/auth/me").status, 401);
    EXPECT_TRUE(websocketUpgradeDeclined(port(), token, WsToken::InHeader));
    HttpClient again = as("gwen");
    EXPECT_TRUE(tokensOf(again).empty());
    const auto [newId, newTokenText] = newToken(again);
    EXPECT_EQ(withToken(newTokenText).get("/api/v1/auth/me").status, 200) << "a new token works";
}

TEST_F(ApiTokens, AUserHasAtMostFiftyTokens)
{
    HttpClient dora = as("dora");
    std::int64_t first = 0;
    for (int i = 0; i < 50; ++i) {
        const auto [id, token] = newToken(dora, "token " + std::to_string(i));
        if (i == 0) first = id;
    }
    const HttpReply refused = create(dora, {{"name", "one too many"}});
    EXPECT_EQ(refused.status, 422) << refused.body;
    EXPECT_EQ(refused.json()["error"]["code"], "limit_exceeded");
    EXPECT_EQ(tokensOf(dora).size(), 50u);
    // Others are not limited by dora's tokens; deleting one makes room.
    EXPECT_EQ(create(as("bob"), {{"name", "bob's"}}).status, 201);
    ASSERT_EQ(revoke(dora, first).status, 204);
    EXPECT_EQ(create(dora, {{"name", "in its place"}}).status, 201);
}

TEST_F(ApiTokens, NameAndExpiryAreChecked)
{
    HttpClient fred = as("fred");
    const auto refused = [&](const nlohmann::json& body) { return create(fred, body).status == 400; };
    EXPECT_TRUE(refused({{"name", ""}}));
    EXPECT_TRUE(refused({{"name", std::string(101, 'n')}}));
    EXPECT_TRUE(refused(nlohmann::json::object()));
    EXPECT_TRUE(refused({{"name", 7}}));
    EXPECT_TRUE(refused({{"name", "x"}, {"expires_in_days", 0}}));
    EXPECT_TRUE(refused({{"name", "x"}, {"expires_in_days", 3651}}));
    EXPECT_TRUE(refused({{"name", "x"}, {"expires_in_days", 1.5}}));
    EXPECT_TRUE(refused({{"name", "x"}, {"scope", "all"}}));
    // As model names (issue 37 L4): no line breaks, other controls or bidirectional overrides.
    EXPECT_TRUE(refused({{"name", "ci\r\nX-Injected: 1"}}));
    EXPECT_TRUE(refused({{"name", "tab\there"}}));
    EXPECT_TRUE(refused({{"name", "gnp\xe2\x80\xae" "exe.js"}}));   // U+202E: displayed as "gnpsj.exe"
    EXPECT_TRUE(refused({{"name", "line\xe2\x80\xa8" "break"}}));  // U+2028
    EXPECT_EQ(create(fred, {{"name", "x\r\ny"}}).json()["error"]["message"],
              "a token's name: the name contains the control character U+000D");
    EXPECT_EQ(fred.request(http::verb::post, "/api/v1/tokens", "{not json").status, 400);
    EXPECT_TRUE(tokensOf(fred).empty()) << "a refused token was stored";

    EXPECT_EQ(create(fred, {{"name", std::string(100, 'n')}}).status, 201);
    std::string umlauts;
    for (int i = 0; i < 100; ++i) umlauts += "\xc3\xb6";   // 100 characters, 200 bytes
    EXPECT_EQ(create(fred, {{"name", umlauts}}).status, 201);
    EXPECT_EQ(create(fred, {{"name", "x"}, {"expires_in_days", 1}}).status, 201);
    EXPECT_EQ(create(fred, {{"name", "x"}, {"expires_in_days", 3650}}).status, 201);
}

} // namespace
} // namespace tlmhub::test
