// Node authentication (issue 19, scale-out): an API node follows a job on a worker node over
// the worker's own WebSocket, as `Authorization: Bearer tlmhub-node.<secret>`. Such a
// connection may log.subscribe to any user's job and do nothing else; without
// --node-secret-file, or with another secret, the upgrade is refused (401).
#include "server/cluster/NodeSecret.h"

#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

using namespace tlmhub::test;
using tlmhub::server::NodeSecret;
namespace fs = std::filesystem;

namespace {

const std::string kSecret = "0123456789abcdef0123456789abcdef-node";

fs::path writeSecret(const fs::path& dir, const std::string& text, fs::perms perms)
{
    const fs::path file = dir / "node-secret";
    std::ofstream(file, std::ios::binary) << text;
    fs::permissions(file, perms);
    return file;
}

std::string loadError(const fs::path& file)
{
    try {
        NodeSecret::load(file);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(NodeSecret, AFileOnlyItsOwnerReadsWithThirtyTwoBytesIsTaken)
{
    const fs::path dir = freshTempDir("node-secret");
    const auto ownerOnly = fs::perms::owner_read | fs::perms::owner_write;
    // A final newline is not part of the secret.
    const NodeSecret secret = NodeSecret::load(writeSecret(dir, kSecret + "\n", ownerOnly));
    EXPECT_EQ(secret.bearerToken(), "tlmhub-node." + kSecret);
    EXPECT_TRUE(secret.matches("tlmhub-node." + kSecret));
    EXPECT_FALSE(secret.matches("tlmhub-node." + kSecret + "\n"));
    EXPECT_FALSE(secret.matches("tlmhub-node." + kSecret.substr(1)));
    EXPECT_FALSE(secret.matches(""));

    EXPECT_NE(loadError(writeSecret(dir, kSecret, ownerOnly | fs::perms::group_read)).find("group or others"),
              std::string::npos);
    EXPECT_NE(loadError(writeSecret(dir, kSecret, ownerOnly | fs::perms::others_read)).find("chmod 600"),
              std::string::npos);
    EXPECT_NE(loadError(writeSecret(dir, std::string(31, 'x') + "\n", ownerOnly)).find("fewer than 32"),
              std::string::npos);
    EXPECT_NE(loadError(writeSecret(dir, std::string(20, 'x') + " " + std::string(20, 'y'), ownerOnly)).find("printable"),
              std::string::npos);
    EXPECT_NE(loadError(dir / "missing").find("cannot be read"), std::string::npos);
    EXPECT_NO_THROW(NodeSecret::load(writeSecret(dir, std::string(32, 'x') + "\n", ownerOnly)));
    fs::remove_all(dir);
}

TEST(NodeSecret, ANodeMayFollowAnyUsersJobAndNothingElse)
{
    const fs::path dir = freshTempDir("node-auth");
    const fs::path secretFile = writeSecret(dir, kSecret + "\n", fs::perms::owner_read | fs::perms::owner_write);
    ServerProcess server(dir / "data", {"--node-secret-file", secretFile.string()});
    createTestUsers(server, {"alice"});
    HttpClient alice = loggedInAs(server, "alice");
    const std::int64_t model = uploadModel(alice, kPositionServo, "servo");
    const auto submitted = alice.post("/api/v1/jobs", {{"model_id", model}, {"stop", 1.0}, {"log_samples", 101}});
    ASSERT_EQ(submitted.status, 201) << submitted.body;
    const std::int64_t job = submitted.json()["id"].get<std::int64_t>();

    const std::string token = "tlmhub-node." + kSecret;
    WsClient node(server.port(), token, 0, WsToken::InHeader, false);
    const auto reply = node.call("log.subscribe", {{"job_id", job}, {"frames", "binary"}});
    ASSERT_EQ(reply["type"], "reply") << reply.dump();
    // The job's events follow, up to its done.
    std::vector<nlohmann::json> events = std::move(node.events);
    node.events.clear();
    auto isDone = [](const nlohmann::json& e) { return e["type"] == "event.done"; };
    while (std::find_if(events.begin(), events.end(), isDone) == events.end()) {
        events.push_back(node.receive(30000));
        ASSERT_FALSE(events.back().is_null()) << "no event.done";
    }
    EXPECT_EQ(std::find_if(events.begin(), events.end(), isDone)->at("state"), "done");
    const bool framed = std::any_of(events.begin(), events.end(), [](const nlohmann::json& e) { return e["type"] == "event.frame"; });
    EXPECT_TRUE(framed);
    EXPECT_FALSE(node.binaryHeaders.empty()) << "frames came as binary messages";

    // Everything else is forbidden; the connection stays open.
    for (const auto& [type, fields] : std::vector<std::pair<std::string, nlohmann::json>>{
             {"model.open", {{"model_id", model}}},
             {"ping", nlohmann::json::object()},
             {"simulate.stop", {{"job_id", job}}},
             {"study.subscribe", {{"study_id", 1}}}}) {
        const auto refused = node.call(type, fields);
        EXPECT_EQ(refused["type"], "error") << type;
        EXPECT_EQ(refused["error"]["code"], "forbidden") << type << ": " << refused.dump();
    }
    // A job that does not exist is not found, as for a user.
    EXPECT_EQ(node.call("log.subscribe", {{"job_id", job + 1000}})["error"]["code"], "not_found");

    // Another secret, or the node token on REST or in the query, is no login.
    EXPECT_TRUE(websocketUpgradeDeclined(server.port(), "tlmhub-node." + kSecret + "x", WsToken::InHeader));
    EXPECT_TRUE(websocketUpgradeDeclined(server.port(), "tlmhub-node.", WsToken::InHeader));
    EXPECT_TRUE(websocketUpgradeDeclined(server.port(), token, WsToken::InQuery));
    HttpClient rest(server.port());
    rest.setToken(token);
    EXPECT_EQ(rest.get("/api/v1/jobs/" + std::to_string(job)).status, 401);
    fs::remove_all(dir);
}

TEST(NodeSecret, WithoutTheFlagANodeTokenIsAnUnknownToken)
{
    const fs::path dir = freshTempDir("node-auth-off");
    ServerProcess server(dir / "data");
    EXPECT_TRUE(websocketUpgradeDeclined(server.port(), "tlmhub-node." + kSecret, WsToken::InHeader));
    fs::remove_all(dir);
}
