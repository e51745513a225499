// POST /jobs and POST /studies with an Idempotency-Key header (protocol/README.md, "Retrying a
// submit"): a retry gets what the first attempt made, never a second job or study. A real
// server shared by the suite's tests; each test uses keys of its own.
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <set>
#include <thread>

using namespace tlmhub::test;

namespace {

class IdempotencyKeys : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dataDir = new std::filesystem::path(freshTempDir("idempotency"));
        server = new ServerProcess(*dataDir, {"--workers", "1"});
        createTestUsers(*server, {"alice", "bob"});
    }
    static void TearDownTestSuite()
    {
        delete server;
        std::filesystem::remove_all(*dataDir);
        delete dataDir;
    }
    static HttpClient as(const std::string& user, const std::string& key)
    {
        HttpClient client = loggedInAs(*server, user);
        client.addHeader("Idempotency-Key", key);
        return client;
    }
    static std::size_t jobsOf(const std::string& user)
    {
        return loggedInAs(*server, user).get("/api/v1/jobs").json().size();
    }
    static nlohmann::json job(double stop) { return {{"hmf", readFile(kPositionServo)}, {"stop", stop}}; }

    static inline std::filesystem::path* dataDir = nullptr;
    static inline ServerProcess* server = nullptr;
};

} // namespace

TEST_F(IdempotencyKeys, ARetriedJobSubmitGetsTheJobItsFirstAttemptMade)
{
    HttpClient alice = as("alice", "retry-job-1");
    const std::size_t before = jobsOf("alice");
    const auto first = alice.post("/api/v1/jobs", job(0.5));
    ASSERT_EQ(first.status, 201) << first.body;
    const auto second = alice.post("/api/v1/jobs", job(0.5));
    ASSERT_EQ(second.status, 201) << second.body;
    EXPECT_EQ(second.json()["id"], first.json()["id"]);
    EXPECT_EQ(second.headers.count("Idempotent-Replayed"), 1u);
    EXPECT_EQ(first.headers.count("Idempotent-Replayed"), 0u);
    EXPECT_EQ(jobsOf("alice"), before + 1);
}

TEST_F(IdempotencyKeys, ARetriedStudySubmitGetsTheStudyItsFirstAttemptMade)
{
    HttpClient alice = as("alice", "retry-study-1");
    const nlohmann::json study = {{"kind", "sweep"}, {"hmf", readFile(kPositionServo)}, {"stop", 0.2},
                                  {"sweep", {{"parameters", {{"GainP.k", {0.01, 0.02}}}}}}};
    const auto first = alice.post("/api/v1/studies", study);
    ASSERT_EQ(first.status, 201) << first.body;
    const auto second = alice.post("/api/v1/studies", study);
    ASSERT_EQ(second.status, 201) << second.body;
    EXPECT_EQ(second.json(), first.json());
    const nlohmann::json studies = alice.get("/api/v1/studies").json()["studies"];
    ASSERT_EQ(studies.size(), 1u) << studies.dump();
    EXPECT_EQ(studies[0]["id"], first.json()["id"]);
}

// Attempts racing on one key make one job: each gets it, or is told to come back (503).
TEST_F(IdempotencyKeys, AttemptsRacingWithOneKeyMakeOneJob)
{
    const std::size_t before = jobsOf("bob");
    constexpr int kAttempts = 6;
    std::vector<HttpReply> replies(kAttempts);
    std::vector<std::thread> attempts;
    for (int i = 0; i < kAttempts; ++i)
        attempts.emplace_back([&, i] { replies[i] = as("bob", "race-1").post("/api/v1/jobs", job(0.5)); });
    for (auto& t : attempts) t.join();
    std::set<std::int64_t> ids;
    for (const HttpReply& r : replies) {
        if (r.status == 503) {
            EXPECT_EQ(r.headers.count("Retry-After"), 1u) << r.body;
            continue;
        }
        ASSERT_EQ(r.status, 201) << r.body;
        ids.insert(r.json()["id"].get<std::int64_t>());
    }
    EXPECT_EQ(ids.size(), 1u);
    EXPECT_EQ(jobsOf("bob"), before + 1);
}

TEST_F(IdempotencyKeys, AKeyReusedWithAnotherRequestIsRefusedNamingTheKey)
{
    HttpClient alice = as("alice", "reused-1");
    ASSERT_EQ(alice.post("/api/v1/jobs", job(0.5)).status, 201);
    const auto other = alice.post("/api/v1/jobs", job(0.6));
    EXPECT_EQ(other.status, 422) << other.body;
    EXPECT_NE(other.body.find("Idempotency-Key"), std::string::npos) << other.body;
    EXPECT_EQ(as("alice", "reused-1").post("/api/v1/studies", job(0.5)).status, 422);
}

// A key belongs to its user: another user's request with it makes their own job.
TEST_F(IdempotencyKeys, AnotherUsersKeyMakesTheirOwnJob)
{
    const auto alices = as("alice", "shared-key").post("/api/v1/jobs", job(0.5));
    const auto bobs = as("bob", "shared-key").post("/api/v1/jobs", job(0.5));
    ASSERT_EQ(alices.status, 201) << alices.body;
    ASSERT_EQ(bobs.status, 201) << bobs.body;
    EXPECT_NE(alices.json()["id"], bobs.json()["id"]);
}

// A request that made nothing leaves its key free for the corrected request; a key that is
// not one (too long, spaces) is refused.
TEST_F(IdempotencyKeys, ARefusedSubmitLeavesItsKeyFreeAndABadKeyIsRefused)
{
    HttpClient alice = as("alice", "fix-and-retry");
    const auto refused = alice.post("/api/v1/jobs", {{"stop", 0.5}});
    EXPECT_EQ(refused.status, 400) << refused.body;
    const auto fixed = alice.post("/api/v1/jobs", job(0.5));
    EXPECT_EQ(fixed.status, 201) << fixed.body;
    EXPECT_EQ(as("alice", std::string(201, 'k')).post("/api/v1/jobs", job(0.5)).status, 400);
    EXPECT_EQ(as("alice", "two words").post("/api/v1/jobs", job(0.5)).status, 400);
}
