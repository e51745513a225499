// End-to-end tests of tlmhub-server: a real server process on an ephemeral loopback port,
// real HTTP and WebSocket clients.
#include "ServerHarness.h"

#include "server/protocol/SchemaValidator.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <thread>

using namespace tlmhub::test;
namespace http = boost::beast::http;
namespace fs = std::filesystem;

namespace {

// One server for the tests that do not restart it; users alice and bob exist.
class ServerApi : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dataDir = new fs::path(freshTempDir("api"));
        server = new ServerProcess(*dataDir);
        createTestUsers(*server, {"alice", "bob"});
    }
    static void TearDownTestSuite()
    {
        delete server;
        fs::remove_all(*dataDir);
        delete dataDir;
    }
    HttpClient as(const std::string& user) { return loggedInAs(*server, user); }
    static fs::path* dataDir;
    static ServerProcess* server;
};
fs::path* ServerApi::dataDir = nullptr;
ServerProcess* ServerApi::server = nullptr;

} // namespace

TEST_F(ServerApi, HealthNeedsNoLoginButEverythingElseDoes)
{
    HttpClient anonymous(server->port());
    const auto health = anonymous.get("/api/v1/health");
    EXPECT_EQ(health.status, 200);
    EXPECT_EQ(health.json()["status"], "ok");
    for (const char* target : {"/api/v1/models", "/api/v1/jobs", "/api/v1/components", "/api/v1/auth/me"}) {
        const auto r = anonymous.get(target);
        EXPECT_EQ(r.status, 401) << target;
        EXPECT_EQ(r.json()["error"]["code"], "unauthorized") << target;
    }
    const auto post = anonymous.post("/api/v1/jobs", {{"hmf", "x"}});
    EXPECT_EQ(post.status, 401);
    anonymous.setToken("not-a-token");
    EXPECT_EQ(anonymous.get("/api/v1/models").status, 401);
}

TEST_F(ServerApi, LoginLogoutAndWrongPassword)
{
    HttpClient c(server->port());
    const auto wrong = c.post("/api/v1/auth/login", {{"username", "alice"}, {"password", "nope-nope"}});
    EXPECT_EQ(wrong.status, 401);
    const std::string token = c.login("alice", "alice-password");
    EXPECT_EQ(token.size(), 64u);
    const auto me = c.get("/api/v1/auth/me");
    EXPECT_EQ(me.json()["username"], "alice");
    EXPECT_EQ(c.request(http::verb::post, "/api/v1/auth/logout").status, 204);
    EXPECT_EQ(c.get("/api/v1/auth/me").status, 401);   // the token is gone
}

TEST_F(ServerApi, RepeatedFailedLoginsAreRateLimited)
{
    HttpClient c(server->port());
    int limited = 0;
    for (int i = 0; i < 8; ++i) {
        const auto r = c.post("/api/v1/auth/login", {{"username", "nobody-" + std::to_string(i % 1)}, {"password", "guessing"}});
        if (r.status == 429) ++limited;
        else EXPECT_EQ(r.status, 401);
    }
    EXPECT_GE(limited, 3);
}

TEST_F(ServerApi, OnlyAdministratorsCreateUsers)
{
    HttpClient alice = as("alice");
    const auto r = alice.post("/api/v1/users", {{"username", "mallory"}, {"password", "12345678x"}, {"role", "admin"}});
    EXPECT_EQ(r.status, 403);
}

TEST_F(ServerApi, NewModelHasHopsansDefaultSettings)
{
    HttpClient alice = as("alice");
    const auto created = alice.post("/api/v1/models", {{"name", "blank"}});
    ASSERT_EQ(created.status, 201) << created.body;
    const auto id = created.json()["id"].get<std::int64_t>();
    const auto model = alice.get("/api/v1/models/" + std::to_string(id)).json();
    const auto& simulation = model["model"]["system"]["simulation"];
    EXPECT_EQ(simulation["start"], 0.0);
    EXPECT_EQ(simulation["stop"], 10.0);
    EXPECT_EQ(simulation["step"], 1e-3);
    EXPECT_EQ(simulation["log_samples"], 2048);
}

TEST_F(ServerApi, UploadDownloadAndOwnership)
{
    HttpClient alice = as("alice");
    const std::string hmf = readFile(kPositionServo);
    const auto id = uploadModel(alice, kPositionServo, "servo");
    const auto download = alice.get("/api/v1/models/" + std::to_string(id) + "?format=hmf");
    EXPECT_EQ(download.status, 200);
    EXPECT_EQ(download.body, hmf);   // stored and returned as is
    const auto asJson = alice.get("/api/v1/models/" + std::to_string(id)).json();
    EXPECT_EQ(asJson["name"], "servo");
    EXPECT_GT(asJson["model"]["system"]["components"].size(), 10u);

    HttpClient bob = as("bob");
    EXPECT_EQ(bob.get("/api/v1/models/" + std::to_string(id)).status, 404);
    EXPECT_EQ(bob.request(http::verb::delete_, "/api/v1/models/" + std::to_string(id)).status, 404);
    EXPECT_EQ(bob.request(http::verb::put, "/api/v1/models/" + std::to_string(id), R"({"name":"stolen"})").status, 404);
    for (const auto& m : bob.get("/api/v1/models").json()) EXPECT_NE(m["id"], id);

    // Examples are everyone's to read and no one's but the admin's to change.
    const auto list = bob.get("/api/v1/models").json();
    std::int64_t example = 0;
    for (const auto& m : list) if (m["is_example"].get<bool>()) example = m["id"].get<std::int64_t>();
    ASSERT_NE(example, 0) << list.dump();
    EXPECT_EQ(bob.get("/api/v1/models/" + std::to_string(example)).status, 200);
    EXPECT_EQ(bob.request(http::verb::delete_, "/api/v1/models/" + std::to_string(example)).status, 403);
}

TEST_F(ServerApi, BadRequestsGetClearErrors)
{
    HttpClient alice = as("alice");
    auto r = alice.request(http::verb::post, "/api/v1/jobs", "{not json");
    EXPECT_EQ(r.status, 400);
    EXPECT_EQ(r.json()["error"]["code"], "bad_json");
    r = alice.request(http::verb::post, "/api/v1/models?name=broken", "<hopsanmodelfile><system", "application/xml");
    EXPECT_EQ(r.status, 400);
    EXPECT_EQ(r.json()["error"]["code"], "invalid_model");
    r = alice.request(http::verb::post, "/api/v1/models?name=teapot",
                      R"(<hopsanmodelfile><system name="Root"><objects><component typename="HydraulicTeapot" )"
                      R"(name="Pot"/></objects></system></hopsanmodelfile>)",
                      "application/xml");
    EXPECT_EQ(r.status, 400);
    EXPECT_EQ(r.json()["error"]["code"], "unknown_component_type") << r.body;
    r = alice.post("/api/v1/jobs", {{"hmf", readFile(kPositionServo)}, {"stop", 1e9}, {"step", 1e-6}});
    EXPECT_EQ(r.json()["error"]["code"], "limit_exceeded") << r.body;
    r = alice.request(http::verb::post, "/api/v1/models", std::string(25u << 20, 'x'), "application/xml");
    EXPECT_EQ(r.status, 413);
    EXPECT_EQ(alice.get("/api/v1/nothing-here").status, 404);
}

TEST_F(ServerApi, RestJobGivesTheSameCsvAsTheCli)
{
    HttpClient alice = as("alice");
    const auto id = uploadModel(alice, kPositionServo, "servo-job");
    const auto submitted = alice.post("/api/v1/jobs", {{"model_id", id}});
    ASSERT_EQ(submitted.status, 201) << submitted.body;
    const std::int64_t job = submitted.json()["id"].get<std::int64_t>();
    const auto done = waitForJobEnd(alice, job);
    ASSERT_EQ(done["state"], "done") << done.dump();
    EXPECT_DOUBLE_EQ(done["progress"].get<double>(), 1.0);
    const auto csv = alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv");
    ASSERT_EQ(csv.status, 200);

    const fs::path out = *dataDir / "cli.csv";
    const std::string cli = fs::path(TLMHUB_SERVER_BIN).parent_path() / "tlmhub-cli";
    const std::string command = "'" + cli + "' run '" + kPositionServo.string() + "' --csv '" + out.string() + "' > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(csv.body, readFile(out));

    HttpClient bob = as("bob");
    EXPECT_EQ(bob.get("/api/v1/jobs/" + std::to_string(job)).status, 404);
    EXPECT_EQ(bob.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv").status, 404);

    const auto json = alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=json&variables=Position_Sensor%23out%23Value").json();
    ASSERT_EQ(json["variables"].size(), 1u) << json.dump().substr(0, 300);
    EXPECT_EQ(json["variables"][0]["data"].size(), json["time"].size());
}

TEST_F(ServerApi, WebSocketErrorsKeepTheConnectionWorking)
{
    HttpClient alice = as("alice");
    const auto id = uploadModel(alice, kPositionServo, "servo-ws");
    WsClient ws(server->port(), alice.login("alice", "alice-password"));
    EXPECT_EQ(ws.hello["protocol"], "tlmhub.v1");

    ws.sendText("{this is not json");
    auto m = ws.receive();
    EXPECT_EQ(m["type"], "error");
    EXPECT_EQ(m["error"]["code"], "bad_json");
    EXPECT_EQ(ws.call("ping")["type"], "reply");

    m = ws.call("no.such.message");
    EXPECT_EQ(m["error"]["code"], "unknown_message_type");
    m = ws.call("component.add", {{"component_type", 42}});
    EXPECT_EQ(m["error"]["code"], "schema_violation");
    EXPECT_EQ(ws.call("ping")["type"], "reply");

    m = ws.call("model.open", {{"model_id", id}});
    ASSERT_EQ(m["type"], "reply") << m.dump();
    m = ws.call("component.add", {{"component_type", "NoSuchComponentType"}});
    EXPECT_EQ(m["error"]["code"], "unknown_component_type");
    EXPECT_NE(m["error"]["message"].get<std::string>().find("NoSuchComponentType"), std::string::npos);

    // A hydraulic port to a mechanic port: refused with the core's reason naming both.
    m = ws.call("connect", {{"from", {{"component", "Mass"}, {"port", "P1"}}},
                            {"to", {{"component", "Tank_C"}, {"port", "P1"}}}});
    EXPECT_EQ(m["error"]["code"], "illegal_connection") << m.dump();
    const std::string reason = m["error"]["message"].get<std::string>();
    EXPECT_NE(reason.find("Mass"), std::string::npos) << reason;
    EXPECT_NE(reason.find("Tank_C"), std::string::npos) << reason;

    m = ws.call("simulate.start", {{"stop", 1e12}, {"step", 1e-3}});
    EXPECT_EQ(m["error"]["code"], "limit_exceeded") << m.dump();
    EXPECT_EQ(ws.call("ping")["type"], "reply");

    // Another user's model cannot be opened.
    HttpClient bob = as("bob");
    WsClient bobWs(server->port(), bob.login("bob", "bob-password"));
    EXPECT_EQ(bobWs.call("model.open", {{"model_id", id}})["error"]["code"], "not_found");
}

// What the server sends with a model in it has the shape the schema gives it: the WebSocket
// replies (x-replies) and GET /models/{id} (ModelDetail), for a model with subsystems.
TEST_F(ServerApi, RepliesCarryingAModelMatchTheSchema)
{
    HttpClient alice = as("alice");
    const auto id = uploadModel(alice, kExampleModels / "Sub System Example.hmf", "subsystems");
    WsClient ws(server->port(), alice.login("alice", testPassword("alice")));
    const auto& schema = tlmhub::server::SchemaValidator::protocol();
    auto expectReplyShape = [&](const std::string& type, const nlohmann::json& fields) {
        const nlohmann::json reply = ws.call(type, fields);
        std::string error;
        EXPECT_EQ(reply["type"], "reply") << type << ": " << reply.dump().substr(0, 300);
        EXPECT_TRUE(schema.validateServerMessage(reply, type, error)) << type << ": " << error;
        return reply;
    };
    const auto opened = expectReplyShape("model.open", {{"model_id", id}});
    EXPECT_FALSE(opened["data"]["model"]["system"]["components"].empty());
    expectReplyShape("model.get", {});
    expectReplyShape("component.add", {{"component_type", "Subsystem"}});
    expectReplyShape("model.create", {{"name", "empty"}});
    std::string error;
    const auto detail = alice.get("/api/v1/models/" + std::to_string(id));
    EXPECT_TRUE(schema.validate("ModelDetail", detail.json(), error)) << error;
}

TEST_F(ServerApi, WebSocketWithoutTokenIsRefused)
{
    EXPECT_ANY_THROW(WsClient(server->port(), "bad-token"));
}

TEST_F(ServerApi, StreamingFramesConcatenateToTheStoredResult)
{
    HttpClient alice = as("alice");
    const auto id = uploadModel(alice, kPositionServo, "servo-stream");
    WsClient ws(server->port(), alice.login("alice", "alice-password"));
    ASSERT_EQ(ws.call("model.open", {{"model_id", id}})["type"], "reply");
    const std::string variable = "Position_Sensor#out#Value";
    // A long enough run that frames arrive while it goes on.
    auto m = ws.call("simulate.start", {{"stop", 200.0}, {"log_samples", 20000}, {"variables", {variable}}, {"rate", 30}});
    ASSERT_EQ(m["type"], "reply") << m.dump();
    const std::int64_t job = m["data"]["job_id"].get<std::int64_t>();
    std::vector<double> streamedTime, streamedValue;
    int framesBeforeDone = 0;
    bool sawProgress = false;
    std::string finalState;
    std::vector<nlohmann::json> pending = ws.events;
    for (int i = 0; i < 100000 && finalState.empty(); ++i) {
        nlohmann::json e;
        if (!pending.empty()) { e = pending.front(); pending.erase(pending.begin()); }
        else e = ws.receive(60000);
        ASSERT_FALSE(e.is_null()) << "no event within 60 s";
        if (e.value("job_id", -1) != job) continue;
        if (e["type"] == "event.progress") sawProgress = true;
        if (e["type"] == "event.frame") {
            ++framesBeforeDone;
            for (const auto& t : e["time"]) streamedTime.push_back(t.get<double>());
            for (const auto& v : e["variables"][variable]) streamedValue.push_back(v.get<double>());
        }
        if (e["type"] == "event.done") finalState = e["state"].get<std::string>();
    }
    EXPECT_EQ(finalState, "done");
    EXPECT_TRUE(sawProgress);
    EXPECT_GE(framesBeforeDone, 2);   // data arrived while running, not only at the end
    const auto stored = alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=json&variables=Position_Sensor%23out%23Value").json();
    ASSERT_EQ(stored["time"].size(), streamedTime.size());
    for (std::size_t i = 0; i < streamedTime.size(); ++i) {
        ASSERT_EQ(stored["time"][i].get<double>(), streamedTime[i]) << i;
        ASSERT_EQ(stored["variables"][0]["data"][i].get<double>(), streamedValue[i]) << i;
    }
}

TEST(ServerRestart, KillDuringAJobKeepsModelsAndRunsTheJobAgain)
{
    const fs::path dir = freshTempDir("restart");
    // The killed server's lease on the job is never renewed: it expires after a second.
    const std::vector<std::string> shortLease{"--lease-seconds", "1"};
    std::int64_t model = 0, job = 0;
    std::string stored;
    {
        ServerProcess server(dir, shortLease);
        HttpClient admin(server.port());
        admin.login("admin", kAdminPassword);
        stored = readFile(kPositionServo);
        auto r = admin.request(http::verb::post, "/api/v1/models?name=kept", stored, "application/xml");
        ASSERT_EQ(r.status, 201);
        model = r.json()["id"].get<std::int64_t>();
        r = admin.post("/api/v1/jobs", {{"model_id", model}, {"stop", 100.0}, {"log_samples", 1000}});
        ASSERT_EQ(r.status, 201) << r.body;
        job = r.json()["id"].get<std::int64_t>();
        for (int i = 0; i < 100 && admin.get("/api/v1/jobs/" + std::to_string(job)).json()["state"] != "running"; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        server.kill9();
    }
    ServerProcess again(dir, shortLease);
    HttpClient admin(again.port());
    admin.login("admin", kAdminPassword);
    EXPECT_EQ(admin.get("/api/v1/models/" + std::to_string(model) + "?format=hmf").body, stored);
    nlohmann::json info;
    for (int i = 0; i < 600; ++i) {
        info = admin.get("/api/v1/jobs/" + std::to_string(job)).json();
        if (info["state"] != "running" && info["state"] != "queued") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_EQ(info["state"], "done") << info.dump();
    const auto result = admin.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=json");
    EXPECT_EQ(result.status, 200);
    EXPECT_EQ(result.json()["time"].size(), 1000u) << result.body.substr(0, 200);
    fs::remove_all(dir);
}

TEST(ServerRestart, SigtermStopsRunningJobsAsInterrupted)
{
    const fs::path dir = freshTempDir("sigterm");
    std::int64_t job = 0;
    {
        ServerProcess server(dir);
        HttpClient admin(server.port());
        admin.login("admin", kAdminPassword);
        auto r = admin.post("/api/v1/jobs", {{"hmf", readFile(kPositionServo)}, {"stop", 3000.0}});
        ASSERT_EQ(r.status, 201) << r.body;
        job = r.json()["id"].get<std::int64_t>();
        // Started, not only claimed: a claimed job that never started goes back to the queue.
        for (int i = 0; i < 600 && admin.get("/api/v1/jobs/" + std::to_string(job)).json()["progress"] <= 0.0; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        const int status = server.terminate();
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << server.output();
    }
    ServerProcess again(dir);
    HttpClient admin(again.port());
    admin.login("admin", kAdminPassword);
    EXPECT_EQ(admin.get("/api/v1/jobs/" + std::to_string(job)).json()["state"], "interrupted");
    fs::remove_all(dir);
}

TEST(ServerComponentLibrary, LoadsOnlyThroughTheStartupFlag)
{
    const fs::path dir = freshTempDir("complib");
    {
        ServerProcess plain(dir / "plain");
        HttpClient c(plain.port());
        c.login("admin", kAdminPassword);
        EXPECT_EQ(c.get("/api/v1/components").body.find("ExampleSquare"), std::string::npos);
    }
    ServerProcess withLib(dir / "lib", {"--component-lib", TLMHUB_EXAMPLE_COMPONENT_LIB});
    EXPECT_NE(withLib.output().find("loaded 1 component types"), std::string::npos) << withLib.output();
    HttpClient c(withLib.port());
    const std::string token = c.login("admin", kAdminPassword);
    EXPECT_NE(c.get("/api/v1/components").body.find("ExampleSquare"), std::string::npos);
    WsClient ws(withLib.port(), token);
    const auto created = ws.call("model.create", {{"name", "squares"}});
    ASSERT_EQ(created["type"], "reply") << created.dump();
    const auto added = ws.call("component.add", {{"component_type", "ExampleSquare"}});
    EXPECT_EQ(added["type"], "reply") << added.dump();
    fs::remove_all(dir);
}

TEST_F(ServerApi, ASlowClientDoesNotHoldUpTheJobOrOthers)
{
    HttpClient alice = as("alice");
    const auto id = uploadModel(alice, kPositionServo, "servo-slow");
    WsClient slow(server->port(), alice.login("alice", "alice-password"));
    ASSERT_EQ(slow.call("model.open", {{"model_id", id}})["type"], "reply");
    // Many frames per second, and this client reads none of them while the job runs.
    const auto started = slow.call("simulate.start", {{"stop", 300.0}, {"log_samples", 50000}, {"rate", 120}});
    ASSERT_EQ(started["type"], "reply") << started.dump();
    const std::int64_t job = started["data"]["job_id"].get<std::int64_t>();
    HttpClient other = as("bob");
    // 3 million steps and about 17 MB of frames, far more than the socket buffers hold:
    // under a second in Release, about 15 s under the sanitizers.
    const auto done = waitForJobEnd(alice, job, std::chrono::seconds(600));
    EXPECT_EQ(done["state"], "done");
    EXPECT_EQ(other.get("/api/v1/health").status, 200);
    // The slow client still gets its events, ending with event.done (never dropped).
    std::string finalState;
    for (int i = 0; i < 100000 && finalState.empty(); ++i) {
        const auto e = slow.receive(20000);
        ASSERT_FALSE(e.is_null());
        if (e["type"] == "event.done") finalState = e["state"].get<std::string>();
    }
    EXPECT_EQ(finalState, "done");
}

TEST_F(ServerApi, ChangingThePasswordEndsSessions)
{
    HttpClient admin = as("admin");
    ASSERT_EQ(admin.post("/api/v1/users", {{"username", "carol"}, {"password", "carol-password"}, {"role", "user"}}).status, 201);
    HttpClient carol(server->port());
    carol.login("carol", "carol-password");
    HttpClient other(server->port());
    other.login("carol", "carol-password");
    auto r = carol.post("/api/v1/auth/password", {{"old_password", "wrong-one!"}, {"new_password", "carol-new-password"}});
    EXPECT_EQ(r.status, 400);
    r = carol.post("/api/v1/auth/password", {{"old_password", "carol-password"}, {"new_password", "carol-new-password"}});
    EXPECT_EQ(r.status, 204) << r.body;
    EXPECT_EQ(other.get("/api/v1/auth/me").status, 401);
    EXPECT_ANY_THROW(carol.login("carol", "carol-password"));
    carol.login("carol", "carol-new-password");
    EXPECT_EQ(carol.get("/api/v1/auth/me").json()["username"], "carol");
}

TEST(ServerQuota, StoredResultsAreLimitedPerUserAndDeletingJobsFreesThem)
{
    const fs::path dir = freshTempDir("quota");
    // A Position Servo result is stored in about 0.5 MB (2 MB uncompressed): after one the
    // quota is used up.
    ServerProcess server(dir, {"--max-stored-bytes-per-user", "400000"});
    HttpClient admin(server.port());
    admin.login("admin", kAdminPassword);
    const std::string hmf = readFile(kPositionServo);
    auto r = admin.post("/api/v1/jobs", {{"hmf", hmf}});
    ASSERT_EQ(r.status, 201) << r.body;
    const std::int64_t first = r.json()["id"].get<std::int64_t>();
    for (int i = 0; i < 600 && admin.get("/api/v1/jobs/" + std::to_string(first)).json()["state"] != "done"; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    r = admin.post("/api/v1/jobs", {{"hmf", hmf}});
    EXPECT_EQ(r.status, 422);
    EXPECT_EQ(r.json()["error"]["code"], "limit_exceeded");
    EXPECT_NE(r.json()["error"]["message"].get<std::string>().find("of 390.6 KiB (--max-stored-bytes-per-user)"),
              std::string::npos)
        << r.body;
    // Deleting the finished job (and its results) makes room again.
    EXPECT_EQ(admin.request(http::verb::delete_, "/api/v1/jobs/" + std::to_string(first)).status, 204);
    EXPECT_EQ(admin.get("/api/v1/jobs/" + std::to_string(first)).status, 404);
    EXPECT_EQ(admin.post("/api/v1/jobs", {{"hmf", hmf}}).status, 201);
    fs::remove_all(dir);
}

TEST(ServerResultExpiry, FinishedJobsAreDeletedAfterTheResultLifetime)
{
    const fs::path dir = freshTempDir("expiry");
    ServerProcess server(dir, {"--result-ttl", "2"});
    HttpClient admin(server.port());
    admin.login("admin", kAdminPassword);
    auto r = admin.post("/api/v1/jobs", {{"hmf", readFile(kPositionServo)}});
    ASSERT_EQ(r.status, 201) << r.body;
    const std::string path = "/api/v1/jobs/" + std::to_string(r.json()["id"].get<std::int64_t>());
    for (int i = 0; i < 600 && admin.get(path).json()["state"] != "done"; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const auto finished = std::chrono::steady_clock::now();
    ASSERT_EQ(admin.get(path).json()["state"], "done");
    EXPECT_EQ(admin.get(path + "/results?format=csv").status, 200);   // kept at first

    // Finished-at has whole-second resolution and sweeps run every second: gone within 2-4 s.
    int status = 200;
    while (status == 200 && std::chrono::steady_clock::now() - finished < std::chrono::seconds(10)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        status = admin.get(path).status;
    }
    EXPECT_EQ(status, 404);
    EXPECT_GE(std::chrono::steady_clock::now() - finished, std::chrono::seconds(1));
    EXPECT_EQ(admin.get(path + "/results?format=csv").status, 404);
    fs::remove_all(dir);
}
