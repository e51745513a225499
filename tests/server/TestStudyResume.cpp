// Resuming a study (POST /studies/{id}/resume, docs/studies.md): a sweep stopped by a server's
// SIGTERM and an optimisation cancelled half-way run only the runs they lack, and end with the
// table an uninterrupted study gives. A real server on a data directory kept across restarts.
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <thread>

using namespace tlmhub::test;
namespace http = boost::beast::http;
namespace fs = std::filesystem;

namespace {

// data/RoundDivide.hmf: Divide#out#Value = 1 / round(Round.in), so each run's output tells
// which value it ran with.
const std::string kReciprocalModel = readFile(kRoundDivide);

class StudyResume : public ::testing::Test {
protected:
    void SetUp() override
    {
        dataDir = freshTempDir("study-resume");
        start();
        createTestUsers(*server, {"alice", "bob"});
    }
    void TearDown() override
    {
        server.reset();
        fs::remove_all(dataDir);
    }
    void start() { server = std::make_unique<ServerProcess>(dataDir, std::vector<std::string>{"--workers", "2"}); }
    HttpClient as(const std::string& user) { return loggedInAs(*server, user); }
    static std::string path(std::int64_t id) { return "/api/v1/studies/" + std::to_string(id); }

    std::int64_t submit(HttpClient& c, const nlohmann::json& study)
    {
        const auto r = c.post("/api/v1/studies", study);
        EXPECT_EQ(r.status, 201) << r.body;
        return r.status == 201 ? r.json()["id"].get<std::int64_t>() : 0;
    }
    // Polls until `done` says so of the study's JSON (at most `seconds`).
    nlohmann::json waitUntil(HttpClient& c, std::int64_t id, const std::function<bool(const nlohmann::json&)>& done,
                             int seconds = 300)
    {
        nlohmann::json study;
        for (int i = 0; i < seconds * 50; ++i) {
            study = c.get(path(id)).json();
            if (done(study)) return study;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        ADD_FAILURE() << "study " << id << " never got there: " << study.dump();
        return study;
    }
    nlohmann::json waitForEnd(HttpClient& c, std::int64_t id)
    {
        return waitUntil(c, id, [](const nlohmann::json& s) {
            const std::string state = s.value("state", "");
            return state != "queued" && state != "running";
        });
    }
    static bool ranAtLeast(const nlohmann::json& study, int runs)
    {
        return study.value("runs_done", 0) + study.value("runs_failed", 0) >= runs;
    }
    nlohmann::json rows(HttpClient& c, std::int64_t id)
    {
        return c.get(path(id) + "/results?format=json").json()["rows"];
    }

    fs::path dataDir;
    std::unique_ptr<ServerProcess> server;
};

} // namespace

// A sweep interrupted by the server's SIGTERM is `interrupted` after the restart; resumed, it
// runs the runs it lacks and each run is in the table once, with the output of its value.
TEST_F(StudyResume, ASweepStoppedByARestartRunsOnlyTheRunsItLacks)
{
    HttpClient alice = as("alice");
    constexpr int kRuns = 2000;
    std::vector<double> values;
    for (int i = 0; i < kRuns; ++i) values.push_back(1 + i % 7);
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", kReciprocalModel},
                                   {"stop", 5},
                                   {"outputs", {{"variables", {"Divide#out#Value"}}}},
                                   {"sweep", {{"parameters", {{"Round.in", values}}}}}});
    waitUntil(alice, id, [](const nlohmann::json& s) { return ranAtLeast(s, 50); });
    EXPECT_EQ(server->terminate(), 0);
    start();
    alice = as("alice");
    const auto stopped = alice.get(path(id)).json();
    ASSERT_EQ(stopped["state"], "interrupted") << stopped.dump();
    const int before = stopped["runs_done"].get<int>();
    ASSERT_GE(before, 50);
    ASSERT_LT(before, kRuns) << "the study ended before the server stopped: nothing to resume";

    // Only its owner resumes it; a second resume while it runs is a conflict.
    HttpClient bob = as("bob");
    EXPECT_EQ(bob.post(path(id) + "/resume", nlohmann::json::object()).status, 404);
    const auto resumed = alice.post(path(id) + "/resume", nlohmann::json::object());
    ASSERT_EQ(resumed.status, 202) << resumed.body;
    EXPECT_EQ(alice.post(path(id) + "/resume", nlohmann::json::object()).status, 409) << "resumed twice";

    const auto study = waitForEnd(alice, id);
    ASSERT_EQ(study["state"], "done") << study.dump();
    EXPECT_EQ(study["runs_done"], kRuns);
    EXPECT_EQ(study["runs_failed"], 0);
    EXPECT_EQ(study["summary"]["runs_reused"], before) << "the stored runs are not run again";
    const auto table = rows(alice, id);
    ASSERT_EQ(table.size(), static_cast<std::size_t>(kRuns));
    std::set<std::int64_t> seen;
    for (const auto& row : table) {
        const auto run = row[0].get<std::int64_t>();
        EXPECT_TRUE(seen.insert(run).second) << "run " << run << " twice";
        EXPECT_EQ(row[2].get<double>(), values.at(run));
        EXPECT_EQ(row[3].get<double>(), 1.0 / values.at(run)) << "run " << run;
    }
    EXPECT_EQ(alice.post(path(id) + "/resume", nlohmann::json::object()).status, 409) << "a done study does not resume";
}

// An optimisation cancelled half-way and resumed walks the same trace as one never stopped:
// the same parameters in every run and the same best point (fixed seed).
TEST_F(StudyResume, AnOptimisationCancelledAndResumedEqualsOneNeverStopped)
{
    HttpClient alice = as("alice");
    const nlohmann::json request = {
        {"kind", "optimise"},
        {"hmf", readFile(kPositionServo)},
        {"stop", 1.5},   // the step comes at 1 s: enough for the gains to show, half the steps of 3 s
        {"optimise", {{"algorithm", "nelder-mead"},
                      {"parameters", {{"GainP.k", {{"min", 0.005}, {"max", 0.08}}}, {"GainI.k", {{"min", 0.0}, {"max", 0.01}}}}},
                      {"objective", {{"terms", {{{"function", "ise"}, {"variable", "Position_Sensor#out#Value"},
                                                 {"reference_variable", "Step#out#Value"}}}}}},
                      {"max_evaluations", 300},
                      {"seed", 7}}}};
    const auto whole = submit(alice, request);
    const auto reference = waitForEnd(alice, whole);
    ASSERT_EQ(reference["state"], "done") << reference.dump();

    const auto id = submit(alice, request);
    waitUntil(alice, id, [](const nlohmann::json& s) { return ranAtLeast(s, 40); });
    const auto cancel = alice.request(http::verb::delete_, path(id));
    ASSERT_TRUE(cancel.status == 200 || cancel.status == 202) << cancel.body;
    const auto cancelled = waitForEnd(alice, id);
    ASSERT_EQ(cancelled["state"], "cancelled") << "it ended before the cancel came: " << cancelled.dump();
    ASSERT_LT(cancelled["runs_done"].get<int>(), reference["runs_done"].get<int>());

    ASSERT_EQ(alice.post(path(id) + "/resume", nlohmann::json::object()).status, 202);
    const auto study = waitForEnd(alice, id);
    ASSERT_EQ(study["state"], "done") << study.dump();
    EXPECT_EQ(study["runs_done"], reference["runs_done"]);
    EXPECT_EQ(study["summary"]["runs_reused"], cancelled["runs_done"]) << "the stored runs are not run again";
    EXPECT_EQ(study["summary"]["best"], reference["summary"]["best"]);
    EXPECT_EQ(rows(alice, id), rows(alice, whole)) << "the resumed trace differs from the uninterrupted one";
}

// A study followed over a WebSocket, cancelled and resumed, is followed again on the same
// socket: the new subscription gets the resumed runs' events to the end, not the old end.
TEST_F(StudyResume, AResumedStudyIsFollowedAgainOnTheSameSocket)
{
    HttpClient alice = as("alice");
    WsClient ws(server->port(), alice.login("alice", testPassword("alice")));
    constexpr int kRuns = 200;
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", readFile(kPositionServo)},
                                   {"stop", 1.5},   // what the runs simulate does not matter here
                                   {"sweep", {{"parameters", {{"GainP.k", {{"from", 0.01}, {"to", 0.04}, {"steps", kRuns}}}}}}}});
    ASSERT_EQ(ws.call("study.subscribe", {{"study_id", id}})["type"], "reply");
    ASSERT_TRUE(alice.request(boost::beast::http::verb::delete_, path(id)).status / 100 == 2);
    const auto cancelled = waitForEnd(alice, id);
    ASSERT_EQ(cancelled["state"], "cancelled") << "the study ended before it was cancelled: nothing to resume";
    // The first subscription's last event, so that it cannot come after the second subscribe.
    const auto isCancelled = [](const nlohmann::json& e) { return e.value("state", "") == "cancelled"; };
    bool cancelSeen = std::any_of(ws.events.begin(), ws.events.end(), isCancelled);
    while (!cancelSeen) {
        const auto event = ws.receive(60000);
        ASSERT_FALSE(event.is_null()) << "the subscriber was not told of the cancel";
        cancelSeen = isCancelled(event);
    }
    ASSERT_EQ(alice.post(path(id) + "/resume", nlohmann::json::object()).status, 202);

    ws.events.clear();
    ASSERT_EQ(ws.call("study.subscribe", {{"study_id", id}})["type"], "reply");
    std::string state;
    std::size_t events = 0;
    const auto take = [&](const nlohmann::json& event) {
        if (event.value("type", "") != "event.study.progress" || event.value("study_id", 0) != id) return;
        ++events;
        state = event.value("state", "");
    };
    for (const auto& event : ws.events) take(event);
    while (state != "done" && state != "failed") {
        const auto event = ws.receive(60000);
        ASSERT_FALSE(event.is_null()) << "no event after the resume; the last state was '" << state << "'";
        ASSERT_NE(event.value("state", ""), "cancelled") << "the old end, not the resumed study: " << event.dump();
        take(event);
    }
    EXPECT_EQ(state, "done");
    EXPECT_GT(events, 1u);
    EXPECT_EQ(waitForEnd(alice, id)["runs_done"], kRuns);
}
