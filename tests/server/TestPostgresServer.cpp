// tlmhub-server on PostgreSQL, through its real binary and sockets: the same REST behaviour
// as on SQLite, and two servers (with data directories of their own) sharing one database
// see each other's users, models, jobs and results, as nodes of one department will.
#include "ServerHarness.h"
#include "TemporaryPostgres.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

using namespace tlmhub::test;
namespace fs = std::filesystem;
namespace http = boost::beast::http;

TEST(PostgresServer, TwoServersOnOneDatabaseShareModelsJobsAndResults)
{
    TemporaryPostgres postgres;
    const fs::path dirA = freshTempDir("pg-node-a"), dirB = freshTempDir("pg-node-b");
    std::int64_t model = 0, job = 0;
    std::string csv;
    {
        ServerProcess nodeA(dirA, {"--database", postgres.uri()});
        EXPECT_NE(nodeA.output().find("PostgreSQL"), std::string::npos) << nodeA.output();
        HttpClient admin(nodeA.port());
        admin.login("admin", kAdminPassword);
        ASSERT_EQ(admin.post("/api/v1/users", {{"username", "alice"}, {"password", "alice-password"}, {"role", "user"}}).status, 201);
        HttpClient alice(nodeA.port());
        alice.login("alice", "alice-password");
        const auto uploaded = alice.request(http::verb::post, "/api/v1/models?name=Servo%20%E6%B0%B4", readFile(kPositionServo),
                                            "application/xml");
        ASSERT_EQ(uploaded.status, 201) << uploaded.body;
        model = uploaded.json()["id"].get<std::int64_t>();
        const auto submitted = alice.post("/api/v1/jobs", {{"model_id", model}});
        ASSERT_EQ(submitted.status, 201) << submitted.body;
        job = submitted.json()["id"].get<std::int64_t>();
        ASSERT_EQ(waitForJobEnd(alice, job)["state"], "done");
        const auto result = alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv");
        ASSERT_EQ(result.status, 200) << result.body;
        csv = result.body;
        EXPECT_GT(csv.size(), 100000u);
    }
    // Node B: no files of node A; the first start's admin and examples are already there.
    ServerProcess nodeB(dirB, {"--database", postgres.uri()});
    EXPECT_EQ(nodeB.output().find("created user 'admin'"), std::string::npos) << nodeB.output();
    HttpClient alice(nodeB.port());
    alice.login("alice", "alice-password");
    const auto summary = alice.get("/api/v1/models/" + std::to_string(model)).json();
    EXPECT_EQ(summary["name"], "Servo \xE6\xB0\xB4");
    EXPECT_EQ(alice.get("/api/v1/models/" + std::to_string(model) + "?format=hmf").body, readFile(kPositionServo));
    EXPECT_EQ(alice.get("/api/v1/jobs/" + std::to_string(job)).json()["state"], "done");
    EXPECT_EQ(alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv").body, csv);
    // Another user still sees none of it; deleting on node B deletes for everyone.
    HttpClient admin(nodeB.port());
    admin.login("admin", kAdminPassword);
    ASSERT_EQ(admin.post("/api/v1/users", {{"username", "bob"}, {"password", "bob-password"}, {"role", "user"}}).status, 201);
    HttpClient bob(nodeB.port());
    bob.login("bob", "bob-password");
    EXPECT_EQ(bob.get("/api/v1/jobs/" + std::to_string(job)).status, 404);
    EXPECT_EQ(alice.request(http::verb::delete_, "/api/v1/jobs/" + std::to_string(job)).status, 204);
    EXPECT_EQ(alice.get("/api/v1/jobs/" + std::to_string(job)).status, 404);
    fs::remove_all(dirA);
    fs::remove_all(dirB);
}
