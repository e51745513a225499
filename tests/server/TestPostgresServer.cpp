// tlmhub-server on PostgreSQL, through its real binary and sockets: the same REST behaviour
// as on SQLite, and two servers (with data directories of their own) sharing one database
// see each other's users, models, jobs and results, as nodes of one department will.
#include "ServerHarness.h"
#include "TemporaryPostgres.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>
#include <thread>
#include <vector>

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

// Issue 37 R1: an API node and a worker started at the same moment on a new database: one
// exited ("cannot create the admin user: username is already taken"), and the worker had
// created 'admin' and seeded the examples. Only API nodes bootstrap, once between them, and
// nodes start in any order: three at once (two API nodes and a worker), ten times.
TEST(PostgresServer, NodesStartedAtOnceOnANewDatabaseBootstrapItOnce)
{
    TemporaryPostgres postgres;
    std::set<std::string> exampleNames;
    for (const auto& entry : fs::directory_iterator(fs::path(TLMHUB_SOURCE_DIR) / "examples"))
        if (entry.path().extension() == ".hmf") exampleNames.insert(entry.path().stem().string());
    ASSERT_FALSE(exampleNames.empty());
    for (int round = 0; round < 10; ++round) {
        const std::string db = "bootstrap" + std::to_string(round);
        const std::string createdb = std::string(TemporaryPostgres::kBinDir) + "/createdb -h 127.0.0.1 -p " +
                                     std::to_string(postgres.port()) + " -U " + TemporaryPostgres::kUser + " " + db;
        ASSERT_EQ(std::system(createdb.c_str()), 0) << createdb;
        const std::vector<std::string> roles = {"api", "worker", "api"};
        std::vector<std::unique_ptr<ServerProcess>> nodes(roles.size());
        std::vector<std::string> failures(roles.size());
        std::vector<std::thread> starting;
        for (std::size_t i = 0; i < roles.size(); ++i) {
            starting.emplace_back([&, i] {
                try {
                    nodes[i] = std::make_unique<ServerProcess>(
                        freshTempDir("pg-bootstrap-" + std::to_string(i)),
                        std::vector<std::string>{"--database", postgres.uri(db), "--role", roles[i]});
                } catch (const std::exception& e) {
                    failures[i] = e.what();
                }
            });
        }
        for (auto& t : starting) t.join();
        for (std::size_t i = 0; i < roles.size(); ++i)
            ASSERT_TRUE(nodes[i]) << "round " << round << ", " << roles[i] << " node: " << failures[i];
        EXPECT_EQ(nodes[1]->output().find("examples: added"), std::string::npos)
            << "round " << round << ": the worker seeded\n" << nodes[1]->output();
        HttpClient admin(nodes[0]->port());
        ASSERT_FALSE(admin.login("admin", kAdminPassword).empty()) << "round " << round;
        std::map<std::string, int> seeded;
        for (const auto& model : admin.get("/api/v1/models").json()) ++seeded[model["name"].get<std::string>()];
        for (const std::string& name : exampleNames)
            EXPECT_EQ(seeded[name], 1) << "round " << round << ": example " << name;
    }
}
