// Runs submitted with keep: false (protocol/README.md, POST /api/v1/jobs): their results are
// given once, by the first read, and then answer 410 naming why; the run stays in the
// history. A real server shared by the suite's tests.
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <map>
#include <thread>

using namespace tlmhub::test;

namespace {

class UnkeptRuns : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        dataDir = new std::filesystem::path(freshTempDir("unkept"));
        server = new ServerProcess(*dataDir, {"--workers", "1"});
        createTestUsers(*server, {"alice"});
    }
    static void TearDownTestSuite()
    {
        delete server;
        std::filesystem::remove_all(*dataDir);
        delete dataDir;
    }
    // A finished run of Position Servo; `keep` false when given so.
    static std::int64_t finishedRun(HttpClient& client, std::optional<bool> keep)
    {
        nlohmann::json body = {{"hmf", readFile(kPositionServo)}, {"stop", 0.2}};
        if (keep) body["keep"] = *keep;
        const auto created = client.post("/api/v1/jobs", body);
        EXPECT_EQ(created.status, 201) << created.body;
        const std::int64_t id = created.json().value("id", std::int64_t{0});
        EXPECT_EQ(waitForJobEnd(client, id)["state"], "done");
        return id;
    }
    static std::string results(std::int64_t id, const std::string& format = "csv")
    {
        return "/api/v1/jobs/" + std::to_string(id) + "/results?format=" + format;
    }

    static inline std::filesystem::path* dataDir = nullptr;
    static inline ServerProcess* server = nullptr;
};

} // namespace

TEST_F(UnkeptRuns, TheResultsAreGivenOnceThenAnswerGoneNamingKeepFalse)
{
    HttpClient alice = loggedInAs(*server, "alice");
    const std::int64_t id = finishedRun(alice, false);
    const auto first = alice.get(results(id));
    ASSERT_EQ(first.status, 200) << first.body;
    EXPECT_EQ(first.body.rfind("time,", 0), 0u) << first.body.substr(0, 100);
    for (const std::string format : {"csv", "json"}) {
        const auto again = alice.get(results(id, format));
        EXPECT_EQ(again.status, 410) << again.body;
        EXPECT_NE(again.body.find("keep: false"), std::string::npos) << again.body;
    }
    const auto job = alice.get("/api/v1/jobs/" + std::to_string(id)).json();
    EXPECT_EQ(job["state"], "done") << "the run stays, without its results";
    EXPECT_EQ(job["results_dropped"], true) << job.dump();
}

TEST_F(UnkeptRuns, AKeptRunsResultsAreReadAsOftenAsAsked)
{
    HttpClient alice = loggedInAs(*server, "alice");
    for (const std::optional<bool> keep : {std::optional<bool>{}, std::optional<bool>{true}}) {
        const std::int64_t id = finishedRun(alice, keep);
        EXPECT_EQ(alice.get(results(id)).status, 200);
        EXPECT_EQ(alice.get(results(id, "json")).status, 200);
        EXPECT_EQ(alice.get(results(id)).status, 200);
    }
}

// Of reads racing for an unkept run's results, exactly one gets them; the others are told they
// are gone, or that the user has too many large replies in the making (503 busy).
TEST_F(UnkeptRuns, OfReadsRacingForTheResultsOneGetsThem)
{
    HttpClient alice = loggedInAs(*server, "alice");
    const std::int64_t id = finishedRun(alice, false);
    constexpr int kReads = 6;
    std::vector<int> statuses(kReads);
    std::vector<std::thread> reads;
    for (int i = 0; i < kReads; ++i)
        reads.emplace_back([&, i] { statuses[i] = loggedInAs(*server, "alice").get(results(id)).status; });
    for (auto& t : reads) t.join();
    EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 200), 1);
    for (const int status : statuses) EXPECT_TRUE(status == 200 || status == 410 || status == 503) << status;
    EXPECT_EQ(alice.get(results(id)).status, 410);
}

// The variables and their units come without the data, and reading them leaves an unkept
// run's results to be read.
TEST_F(UnkeptRuns, TheVariablesWithTheirUnitsAreReadWithoutUsingUpTheResults)
{
    HttpClient alice = loggedInAs(*server, "alice");
    const std::int64_t id = finishedRun(alice, false);
    const std::string path = "/api/v1/jobs/" + std::to_string(id) + "/variables";
    const auto listed = alice.get(path);
    ASSERT_EQ(listed.status, 200) << listed.body;
    std::map<std::string, std::string> units;
    const nlohmann::json variables = listed.json()["variables"];
    for (const auto& v : variables) units[v["name"].get<std::string>()] = v["unit"].get<std::string>();
    EXPECT_EQ(units.at("4_3_Servo_Valve#PA#Pressure"), "Pa") << listed.body;
    EXPECT_EQ(listed.body.find("data"), std::string::npos) << "no data";
    const auto given = alice.get(results(id, "json"));
    ASSERT_EQ(given.status, 200) << "listing the variables used nothing up";
    EXPECT_EQ(given.json()["variables"].size(), units.size());
    EXPECT_EQ(alice.get(path).status, 410) << "once the results are given, they are gone";
}
