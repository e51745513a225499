// A model's run history through a real server (issue 38): GET /jobs?model_id= lists the runs
// the caller may see, newest first, a page at a time, with the overrides each was submitted
// with and the values it used that the model's text no longer says; PATCH /jobs/{id} names and
// pins a run; beyond --max-unpinned-runs-per-model the oldest unpinned runs lose their results
// (410), pinned ones never. On SQLite here, on
// PostgreSQL in PostgresServer.RunHistoryAsOnSqlite; who sees a student's copy's runs in
// Labs.ACopysRunHistoryIsTheStudentsAndTheirStaffs.
#include "ServerHarness.h"
#include "TemporaryPostgres.h"
#include "TestFiles.h"

#include "server/jobs/RunParameterDifferences.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tlmhub::test {

namespace {

namespace http = boost::beast::http;

std::vector<std::int64_t> historyIds(const HttpReply& reply)
{
    std::vector<std::int64_t> ids;
    for (const auto& job : reply.json()) ids.push_back(job["id"].get<std::int64_t>());
    return ids;
}

// Runs `modelId` as `client` with `parameters` to its end (done); the job's id.
std::int64_t runToEnd(HttpClient& client, std::int64_t modelId, nlohmann::json parameters = nlohmann::json::object())
{
    const auto submitted = client.post("/api/v1/jobs", {{"model_id", modelId}, {"parameters", parameters}});
    EXPECT_EQ(submitted.status, 201) << submitted.body;
    const std::int64_t id = submitted.json()["id"].get<std::int64_t>();
    EXPECT_EQ(waitForJobEnd(client, id)["state"], "done");
    return id;
}

std::int64_t exampleModelId(HttpClient& client, const std::string& name)
{
    for (const auto& m : client.get("/api/v1/models").json())
        if (m["name"] == name && m["is_example"] == true) return m["id"].get<std::int64_t>();
    ADD_FAILURE() << "no example named " << name;
    return 0;
}

std::vector<std::string> runHistoryServerFlags()
{
    return {"--max-unpinned-runs-per-model", "2", "--examples-dir", kExampleModels.string()};
}

void checkRunHistory(const ServerProcess& server)
{
    createTestUsers(server, {"hana", "ivo"});
    HttpClient hana = loggedInAs(server, "hana"), ivo = loggedInAs(server, "ivo"), admin = loggedInAs(server, "admin");
    const std::int64_t own = uploadModel(hana, kPositionServo, "servo");
    const std::int64_t other = uploadModel(hana, kPositionServo, "servo2");
    const std::string history = "/api/v1/jobs?model_id=" + std::to_string(own);

    // Four runs of her model (one with overrides) and one of another model.
    const std::int64_t first = runToEnd(hana, own, {{"GainP.k", "0.02"}});
    const std::int64_t second = runToEnd(hana, own);
    runToEnd(hana, other);
    const std::int64_t third = runToEnd(hana, own, {{"GainP.k", 0.05}});
    const std::int64_t fourth = runToEnd(hana, own);

    const auto all = hana.get(history);
    ASSERT_EQ(all.status, 200) << all.body;
    EXPECT_EQ(historyIds(all), (std::vector<std::int64_t>{fourth, third, second, first}));
    const nlohmann::json oldest = all.json()[3];
    EXPECT_EQ(oldest["parameters"], (nlohmann::json{{"GainP.k", "0.02"}})) << "the stored overrides";
    EXPECT_EQ(all.json()[1]["parameters"], (nlohmann::json{{"GainP.k", "0.05"}}));
    EXPECT_EQ(all.json()[0]["parameters"], nlohmann::json::object());
    EXPECT_EQ(oldest["owner"], "hana");
    EXPECT_EQ(oldest["model_id"], own);
    EXPECT_EQ(oldest["settings"]["stop"], all.json()[0]["settings"]["stop"]);
    EXPECT_EQ(oldest["name"], "");
    EXPECT_EQ(oldest["pinned"], false);
    // What each run used where the model's text says otherwise: the overrides only, named as
    // the model names the parameter (GainP.k is the start value of its input k).
    EXPECT_EQ(oldest["differing_parameters"], (nlohmann::json{{"GainP.k#Value", "0.02"}}));
    EXPECT_EQ(all.json()[1]["differing_parameters"], (nlohmann::json{{"GainP.k#Value", "0.05"}}));
    EXPECT_EQ(all.json()[0]["differing_parameters"], nlohmann::json::object());

    // Pages of two.
    const auto page1 = hana.get(history + "&limit=2");
    EXPECT_EQ(historyIds(page1), (std::vector<std::int64_t>{fourth, third}));
    EXPECT_EQ(historyIds(hana.get(history + "&limit=2&before=" + std::to_string(third))),
              (std::vector<std::int64_t>{second, first}));
    EXPECT_EQ(hana.get(history + "&limit=0").status, 400);
    EXPECT_EQ(hana.get(history + "&limit=101").status, 400);
    EXPECT_EQ(hana.get(history + "&before=x").status, 400);
    EXPECT_EQ(hana.get("/api/v1/jobs?model_id=abc").status, 400);

    // Only two unpinned runs keep their results: the two oldest lost theirs, and stay listed.
    for (const std::int64_t job : {first, second}) {
        const auto info = hana.get("/api/v1/jobs/" + std::to_string(job)).json();
        EXPECT_EQ(info["results_dropped"], true) << job;
        EXPECT_EQ(info["state"], "done");
        const auto results = hana.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv");
        EXPECT_EQ(results.status, 410) << results.body;
        EXPECT_EQ(results.json()["error"]["code"], "gone");
        EXPECT_NE(results.body.find("--max-unpinned-runs-per-model"), std::string::npos) << results.body;
    }
    EXPECT_EQ(hana.get("/api/v1/jobs/" + std::to_string(third) + "/results?format=csv").status, 200);

    // Pinned and named, the third run keeps its results when two more runs come.
    const std::string thirdPath = "/api/v1/jobs/" + std::to_string(third);
    const auto pinned = hana.request(http::verb::patch, thirdPath, R"({"pinned": true, "name": "k = 0.05 \u00b5"})");
    ASSERT_EQ(pinned.status, 200) << pinned.body;
    EXPECT_EQ(pinned.json()["pinned"], true);
    EXPECT_EQ(pinned.json()["name"], "k = 0.05 \xc2\xb5");
    EXPECT_EQ(hana.request(http::verb::patch, thirdPath, R"({"name": "line\nbreak"})").status, 400);
    EXPECT_EQ(hana.request(http::verb::patch, thirdPath, R"({"colour": "red"})").status, 400);
    const std::int64_t fifth = runToEnd(hana, own);
    const std::int64_t sixth = runToEnd(hana, own);
    EXPECT_EQ(hana.get(thirdPath + "/results?format=csv").status, 200) << "a pinned run keeps its results";
    EXPECT_EQ(hana.get("/api/v1/jobs/" + std::to_string(fourth) + "/results?format=csv").status, 410);
    for (const std::int64_t kept : {fifth, sixth})
        EXPECT_EQ(hana.get("/api/v1/jobs/" + std::to_string(kept) + "/results?format=csv").status, 200);
    EXPECT_EQ(hana.get(history).json()[3]["name"], "k = 0.05 \xc2\xb5");

    // The model's gain changes to what the third run was given: that run now used the model's
    // text, the runs without overrides used the old gain.
    std::string edited = readFile(kPositionServo);
    const std::string oldGain = R"(value="0.0264249" type="double" name="k#Value")";
    ASSERT_NE(edited.find(oldGain), std::string::npos);
    edited.replace(edited.find(oldGain), oldGain.size(), R"(value="0.05" type="double" name="k#Value")");
    const auto updated = hana.request(http::verb::put, "/api/v1/models/" + std::to_string(own), edited, "application/xml");
    ASSERT_EQ(updated.status, 200) << updated.body;
    const auto afterEdit = hana.get(history).json();
    ASSERT_EQ(afterEdit.size(), 6u);
    EXPECT_EQ(afterEdit[0]["id"], sixth);
    EXPECT_EQ(afterEdit[0]["differing_parameters"], (nlohmann::json{{"GainP.k#Value", "0.0264249"}}));
    EXPECT_EQ(afterEdit[3]["id"], third);
    EXPECT_EQ(afterEdit[3]["differing_parameters"], nlohmann::json::object());
    EXPECT_EQ(afterEdit[5]["differing_parameters"], (nlohmann::json{{"GainP.k#Value", "0.02"}}));
    EXPECT_FALSE(afterEdit[5].contains("differing_parameters_truncated"));

    // Others: no history of her model, no naming or pinning of her runs; the administrator sees it all.
    EXPECT_EQ(ivo.get(history).status, 404);
    EXPECT_EQ(ivo.request(http::verb::patch, thirdPath, R"({"pinned": false})").status, 404);
    EXPECT_EQ(hana.get(thirdPath).json()["pinned"], true);
    const auto seenByAdmin = admin.get(history);
    ASSERT_EQ(seenByAdmin.status, 200);
    EXPECT_EQ(historyIds(seenByAdmin).size(), 6u);
    EXPECT_EQ(admin.request(http::verb::patch, thirdPath, R"({"name": "admin's"})").status, 200);

    // An example everyone runs: each user's history of it holds their own runs only.
    const std::int64_t example = exampleModelId(hana, "Position Servo");
    const std::int64_t hanasRun = runToEnd(hana, example);
    const std::int64_t ivosRun = runToEnd(ivo, example);
    const std::string exampleHistory = "/api/v1/jobs?model_id=" + std::to_string(example);
    EXPECT_EQ(historyIds(hana.get(exampleHistory)), std::vector<std::int64_t>{hanasRun});
    EXPECT_EQ(historyIds(ivo.get(exampleHistory)), std::vector<std::int64_t>{ivosRun});
    EXPECT_EQ(historyIds(admin.get(exampleHistory)), (std::vector<std::int64_t>{ivosRun, hanasRun}));
    EXPECT_EQ(hana.get("/api/v1/jobs?model_id=999999").status, 404);
    EXPECT_EQ(hana.get("/api/v1/jobs").json().size(), 8u) << "without model_id: all her jobs, as before";
}

TEST(RunHistory, ListsPinsAndDropsResultsOfUnpinnedRuns)
{
    ServerProcess server(freshTempDir("run-history"), runHistoryServerFlags());
    checkRunHistory(server);
}

// Jobs stored before a job kept the values it used are compared through their model's text and
// overrides; a model that no longer loads differs in everything, listed up to the limit.
TEST(RunParameterDifferences, AJobStoredWithoutItsValuesIsComparedThroughItsModelText)
{
    const std::string original = readFile(kPositionServo);
    std::string current = original;
    const std::string oldGain = R"(value="0.0264249" type="double" name="k#Value")";
    ASSERT_NE(current.find(oldGain), std::string::npos);
    current.replace(current.find(oldGain), oldGain.size(), R"(value="0.05" type="double" name="k#Value")");
    server::RunParameterDifferences differences([&] { return current; }, server::ModelLimits{});
    server::JobRequest run;
    run.hmf = original;
    bool truncated = true;
    EXPECT_EQ(differences.differing(differences.usedBy(run), 100, truncated),
              (server::RunParameterDifferences::Texts{{"GainP.k#Value", "0.0264249"}}));
    EXPECT_FALSE(truncated);
    run.parameters = {{"GainP.k", "0.05"}, {"Mass.m", "2"}};
    EXPECT_EQ(differences.differing(differences.usedBy(run), 100, truncated),
              (server::RunParameterDifferences::Texts{{"Mass.m", "2"}}));

    server::RunParameterDifferences againstNothing([] { return std::string("<not a model/>"); }, server::ModelLimits{});
    const auto everything = againstNothing.differing(againstNothing.usedBy(run), 3, truncated);
    EXPECT_EQ(everything.size(), 3u);
    EXPECT_TRUE(truncated);
}

TEST(PostgresServer, RunHistoryAsOnSqlite)
{
    TemporaryPostgres postgres;
    std::vector<std::string> flags = runHistoryServerFlags();
    flags.insert(flags.end(), {"--database", postgres.uri()});
    ServerProcess server(freshTempDir("run-history-pg"), flags);
    checkRunHistory(server);
}

} // namespace
} // namespace tlmhub::test
