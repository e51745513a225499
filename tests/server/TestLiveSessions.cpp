// Live sessions (docs/live-sessions.md): the pacing arithmetic with a clock of the test's own,
// then a real server driven over the WebSocket with Position Servo (3 s, step 1e-4; the
// SignalStep `Step` has y_0 0.2, y_A 0.5, t_step 1 s). Tests assert order and outcomes;
// wall-clock bounds are loose (CI has 2 cores under sanitizers).
#include "ServerHarness.h"

#include "core/Results.h"
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "server/live/LivePacer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

using namespace tlmhub::test;
using tlmhub::server::LivePacer;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace {

const std::string kStepOut = "Step#out#Value";
constexpr double kServoStep = 1e-4;

// ---------------------------------------------------------------- pacing, injected clock

TEST(LivePacer, StepsDueFollowTheClockTimesTheSpeed)
{
    const LivePacer::Clock::time_point t0{};
    LivePacer pacer(0.001, 2.0, t0, false);
    EXPECT_EQ(pacer.due(t0, 1'000'000), 0u);
    EXPECT_EQ(pacer.due(t0 + 100ms, 1'000'000), 200u);   // 0.1 s × 2 = 0.2 model s
    pacer.taken(150);
    EXPECT_EQ(pacer.due(t0 + 100ms, 1'000'000), 50u);
    EXPECT_EQ(pacer.due(t0 + 100ms, 20), 20u);           // bounded by the tick's slice
    pacer.taken(50);
    EXPECT_EQ(pacer.due(t0 + 100ms, 1'000'000), 0u);     // never ahead of the clock
    EXPECT_EQ(pacer.due(t0 + 150ms, 1'000'000), 100u);
}

TEST(LivePacer, PausedOwesNothingAndAResumeOrANewSpeedPacesFromThen)
{
    const LivePacer::Clock::time_point t0{};
    LivePacer pacer(0.01, 1.0, t0, true);
    EXPECT_EQ(pacer.due(t0 + 500ms, 1000), 0u);
    pacer.resume(t0 + 500ms);
    EXPECT_EQ(pacer.due(t0 + 600ms, 1000), 10u);   // only the 0.1 s since the resume
    pacer.taken(10);
    pacer.pause(t0 + 600ms);
    EXPECT_EQ(pacer.due(t0 + 2s, 1000), 0u);
    pacer.resume(t0 + 2s);
    pacer.setSpeed(0.5, t0 + 2s);
    EXPECT_EQ(pacer.due(t0 + 2200ms, 1000), 10u);  // 0.2 s × 0.5
    pacer.setSpeed(std::nullopt, t0 + 2200ms);    // max: a slice at a time
    EXPECT_EQ(pacer.due(t0 + 2200ms, 1000), 1000u);
}

TEST(LivePacer, FarBehindItPacesFromWhereItIsAndMeasuresTheShortfall)
{
    const LivePacer::Clock::time_point t0{};
    LivePacer pacer(0.001, 1.0, t0, false);
    // Half the steps due in each of the first 2 s: no burst to catch up afterwards.
    EXPECT_EQ(pacer.due(t0 + 500ms, 1'000'000), 500u);
    pacer.taken(250);
    EXPECT_FALSE(pacer.measure(t0 + 500ms));
    EXPECT_EQ(pacer.due(t0 + 1000ms, 1'000'000), 750u);
    pacer.taken(250);
    const auto first = pacer.measure(t0 + 1000ms);
    ASSERT_TRUE(first);
    EXPECT_DOUBLE_EQ(*first, 0.5);
    EXPECT_EQ(pacer.due(t0 + 2500ms, 1'000'000), 0u);     // more than a second behind: re-paced
    EXPECT_EQ(pacer.due(t0 + 2600ms, 1'000'000), 100u);   // from 2.5 s on
    pacer.taken(100);
    const auto second = pacer.measure(t0 + 2600ms);
    ASSERT_TRUE(second);
    EXPECT_NEAR(*second, 0.1 / 1.6, 1e-12);
}

// ---------------------------------------------------------------- the server

std::string errorCode(const nlohmann::json& reply)
{
    return reply.value("type", "") == "error" ? reply["error"].value("code", "") : "";
}

std::string errorMessage(const nlohmann::json& reply)
{
    return reply.value("type", "") == "error" ? reply["error"].value("message", "") : "";
}

class LiveSessionsBase : public ::testing::Test {
protected:
    static void startServer(std::vector<std::string> flags, std::initializer_list<const char*> users)
    {
        dataDir = new fs::path(freshTempDir("live"));
        server = new ServerProcess(*dataDir, std::move(flags));
        createTestUsers(*server, users);
    }
    static void stopServer()
    {
        delete server;
        fs::remove_all(*dataDir);
        delete dataDir;
    }
    // A user's own copy of Position Servo (nobody else may read it).
    std::int64_t servoOf(HttpClient& user) { return uploadModel(user, kPositionServo, "LiveServo"); }
    WsClient socketOf(HttpClient& user) { return WsClient(server->port(), user.token()); }

    // The session id of a started session (the test fails if it is refused).
    std::int64_t start(WsClient& ws, std::int64_t model, nlohmann::json fields = nlohmann::json::object())
    {
        fields["model_id"] = model;
        if (!fields.contains("variables")) fields["variables"] = {kStepOut};
        const nlohmann::json reply = ws.call("live.start", fields);
        EXPECT_EQ(reply.value("type", ""), "reply") << reply.dump();
        return reply.value("type", "") == "reply" ? reply["data"]["session_id"].get<std::int64_t>() : 0;
    }
    // Events received until `done` says so (kept in order, the last one included), or null
    // after `timeoutMs` without it.
    nlohmann::json until(WsClient& ws, const std::function<bool(const nlohmann::json&)>& done,
                         std::vector<nlohmann::json>* seen = nullptr, int timeoutMs = 15000)
    {
        // Events that came in between a call's reply are looked at first.
        while (!ws.events.empty()) {
            nlohmann::json e = std::move(ws.events.front());
            ws.events.erase(ws.events.begin());
            if (seen) seen->push_back(e);
            if (done(e)) return e;
        }
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
        while (std::chrono::steady_clock::now() < deadline) {
            nlohmann::json e = ws.receive(timeoutMs);
            if (e.is_null()) break;
            if (seen) seen->push_back(e);
            if (done(e)) return e;
        }
        return nullptr;
    }
    static bool isFrame(const nlohmann::json& e) { return e.value("type", "") == "event.live.frame"; }
    static bool isState(const nlohmann::json& e, const std::string& state)
    {
        return e.value("type", "") == "event.live.state" && e.value("state", "") == state;
    }
    static double stepOut(const nlohmann::json& frame) { return frame["variables"][kStepOut].back().get<double>(); }

    static fs::path* dataDir;
    static ServerProcess* server;
};
fs::path* LiveSessionsBase::dataDir = nullptr;
ServerProcess* LiveSessionsBase::server = nullptr;

// One server for the suite, with the default limits; each test has users of its own.
class LiveSessions : public LiveSessionsBase {
protected:
    static void SetUpTestSuite()
    {
        startServer({}, {"pace", "setter", "restart", "stepper", "limited", "owner", "intruder", "leaver", "fast",
                     "binary", "watcher", "recorder", "recowner", "recsnoop", "animator"});
    }
    static void TearDownTestSuite() { stopServer(); }
};

// A node that runs one session at most, ends a session after 1 s without a message, and
// records at most 5 samples of one (the job log limit).
class LiveSessionLimits : public LiveSessionsBase {
protected:
    static void SetUpTestSuite()
    {
        startServer({"--max-live-sessions", "1", "--live-idle-timeout", "1", "--max-log-samples", "5"},
                    {"first", "second", "idler", "longrec"});
    }
    static void TearDownTestSuite() { stopServer(); }
};

// live.start on a node with one place, which another test's session may still hold for a moment.
nlohmann::json startOnceThePlaceIsFree(WsClient& ws, const nlohmann::json& params)
{
    nlohmann::json reply;
    for (int tries = 0; tries < 100; ++tries) {
        reply = ws.call("live.start", params);
        if (errorCode(reply) != "busy") break;
        std::this_thread::sleep_for(50ms);
    }
    return reply;
}

} // namespace

TEST_F(LiveSessions, ModelTimeFollowsTheWallClockTimesTheSpeedOrTheShortfallIsReported)
{
    HttpClient user = loggedInAs(*server, "pace");
    WsClient ws = socketOf(user);
    const double speed = 0.5;
    const std::int64_t id = start(ws, servoOf(user), {{"speed", speed}});
    ASSERT_GT(id, 0);
    std::vector<nlohmann::json> seen;
    const nlohmann::json last = until(ws, [](const nlohmann::json& e) {
        return isFrame(e) && e["wall_time"].get<double>() >= 2.5;
    }, &seen);
    ASSERT_TRUE(last.is_object()) << "no frame after 2.5 s of wall time";
    EXPECT_TRUE(isState(seen.front(), "running")) << seen.front().dump();
    double previous = -1.0;
    bool shortfallReported = false;
    for (const nlohmann::json& e : seen) {
        if (isState(e, "running") && e["achieved_speed"].get<double>() < speed) shortfallReported = true;
        if (!isFrame(e)) continue;
        EXPECT_EQ(e["session_id"], id);
        const double modelTime = e["model_time"].get<double>();
        EXPECT_GE(modelTime, previous);
        previous = modelTime;
        // Never ahead of the wall clock (a tick's steps are due when it starts).
        EXPECT_LE(modelTime, e["wall_time"].get<double>() * speed + 0.05) << e.dump();
    }
    const double expected = last["wall_time"].get<double>() * speed;
    // Behind it only by a loose margin, or saying so (achieved_speed below the speed).
    if (last["model_time"].get<double>() < 0.5 * expected) {
        EXPECT_TRUE(shortfallReported) << last.dump();
    }
    EXPECT_EQ(last["time"].size(), last["variables"][kStepOut].size());
    // Frames come at the display rate (30 a second by default), within a loose margin for a busy
    // machine: a tick that sent none because it came a little early once made it about 19.
    const double firstWall = 0.5, lastWall = last["wall_time"].get<double>();
    const auto frames = std::count_if(seen.begin(), seen.end(), [&](const nlohmann::json& e) {
        return isFrame(e) && e["wall_time"].get<double>() > firstWall;
    });
    EXPECT_GE(static_cast<double>(frames), 0.8 * 30 * (lastWall - firstWall)) << frames << " frames";

    // A new speed is acknowledged with its state, and paces from then on.
    const nlohmann::json faster = ws.call("live.speed", {{"session_id", id}, {"speed", 2.0}});
    ASSERT_EQ(faster.value("type", ""), "reply") << faster.dump();
    EXPECT_EQ(faster["data"]["speed"], 2.0);
    EXPECT_TRUE(until(ws, [](const nlohmann::json& e) { return isState(e, "running") && e["speed"] == 2.0; }).is_object());
    const nlohmann::json stopped = ws.call("live.stop", {{"session_id", id}});
    EXPECT_EQ(stopped["data"]["state"], "stopped") << stopped.dump();
    EXPECT_EQ(errorCode(ws.call("live.pause", {{"session_id", id}})), "not_found");
}

TEST_F(LiveSessions, ASetChangesTheStreamedVariableFromTheNextStepOn)
{
    HttpClient user = loggedInAs(*server, "setter");
    WsClient ws = socketOf(user);
    const nlohmann::json reply = ws.call("live.start", {{"model_id", servoOf(user)}, {"paused", true}, {"speed", 0.5},
                                                        {"variables", {kStepOut}}});
    ASSERT_EQ(reply.value("type", ""), "reply") << reply.dump();
    const std::int64_t id = reply["data"]["session_id"].get<std::int64_t>();
    EXPECT_EQ(reply["data"]["variables"], nlohmann::json::array({kStepOut}));
    EXPECT_EQ(reply["data"]["step"].get<double>(), kServoStep);
    bool listed = false;
    for (const auto& v : reply["data"]["live_values"]) listed = listed || v["name"] == "Step.y_0";
    EXPECT_TRUE(listed) << reply["data"]["live_values"].dump();
    EXPECT_TRUE(until(ws, [](const nlohmann::json& e) { return isState(e, "paused"); }).is_object());

    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 10}}).value("type", ""), "reply");
    nlohmann::json frame = until(ws, [](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > 0; });
    ASSERT_TRUE(frame.is_object());
    EXPECT_NEAR(frame["model_time"].get<double>(), 10 * kServoStep, 1e-12);
    EXPECT_EQ(stepOut(frame), 0.2);

    const nlohmann::json set = ws.call("live.set", {{"session_id", id}, {"name", "Step.y_0"}, {"value", 0.9}});
    ASSERT_EQ(set.value("type", ""), "reply") << set.dump();
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 1}}).value("type", ""), "reply");
    frame = until(ws, [](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > 10.5 * kServoStep; });
    ASSERT_TRUE(frame.is_object());
    EXPECT_NEAR(frame["model_time"].get<double>(), 11 * kServoStep, 1e-12);
    EXPECT_EQ(stepOut(frame), 0.9);

    // Running, many sets of one name in a burst: they are coalesced and the last one wins.
    // (The step comes later than the run goes: only y_0 shows.)
    ASSERT_EQ(ws.call("live.set", {{"session_id", id}, {"name", "Step.t_step"}, {"value", 100}}).value("type", ""), "reply");
    ASSERT_EQ(ws.call("live.resume", {{"session_id", id}})["data"]["state"], "running");
    for (int i = 1; i <= 50; ++i)
        ws.sendText(nlohmann::json{{"id", "burst"}, {"type", "live.set"}, {"session_id", id}, {"name", "Step.y_0"},
                                   {"value", i / 100.0}}.dump());
    std::vector<nlohmann::json> seen;
    int replies = 0;
    until(ws, [&](const nlohmann::json& e) { return e.value("id", "") == "burst" && ++replies == 50; }, &seen);
    EXPECT_EQ(replies, 50);
    for (const auto& e : seen) EXPECT_NE(e.value("type", ""), "error") << e.dump();
    frame = until(ws, [](const nlohmann::json& e) { return isFrame(e) && stepOut(e) == 0.5; });
    ASSERT_TRUE(frame.is_object()) << "the last value never showed";
    // Once shown, it stays.
    for (int i = 0; i < 3; ++i) {
        frame = until(ws, isFrame);
        ASSERT_TRUE(frame.is_object());
        EXPECT_EQ(stepOut(frame), 0.5);
    }
}

TEST_F(LiveSessions, ARecordedSessionIsARunInTheModelsHistoryWithItsSamplesAndChanges)
{
    HttpClient user = loggedInAs(*server, "recorder");
    WsClient ws = socketOf(user);
    const std::int64_t model = servoOf(user);
    const std::int64_t id = start(ws, model, {{"paused", true}});
    ASSERT_GT(id, 0);
    ASSERT_TRUE(until(ws, [](const nlohmann::json& e) { return isState(e, "paused"); }).is_object());
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 10}}).value("type", ""), "reply");
    ASSERT_TRUE(until(ws, [](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > 0; }).is_object());
    ASSERT_EQ(ws.call("live.set", {{"session_id", id}, {"name", "Step.y_0"}, {"value", 0.9}}).value("type", ""), "reply");
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 1}}).value("type", ""), "reply");
    ASSERT_TRUE(until(ws, [](const nlohmann::json& e) {
        return isFrame(e) && e["model_time"].get<double>() > 10.5 * kServoStep;
    }).is_object());
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 5}}).value("type", ""), "reply");
    ASSERT_TRUE(until(ws, [](const nlohmann::json& e) {
        return isFrame(e) && e["model_time"].get<double>() > 15.5 * kServoStep;
    }).is_object());

    const nlohmann::json recorded = ws.call("live.record", {{"session_id", id}});
    ASSERT_EQ(recorded.value("type", ""), "reply") << recorded.dump();
    const nlohmann::json& data = recorded["data"];
    const std::int64_t job = data["job_id"].get<std::int64_t>();
    EXPECT_EQ(data["full"], false);
    EXPECT_EQ(data["samples"], 4) << "start, after 10, 11 and 16 steps: " << data.dump();
    ASSERT_EQ(data["changes"].size(), 1u) << data.dump();
    EXPECT_EQ(data["changes"][0]["name"], "Step.y_0");
    EXPECT_EQ(data["changes"][0]["value"], 0.9);
    const double changedAt = data["changes"][0]["time"].get<double>();
    EXPECT_NEAR(changedAt, 10 * kServoStep, 1e-12);
    // The session goes on after a recording; stopping it leaves the run.
    EXPECT_EQ(ws.call("live.stop", {{"session_id", id}})["data"]["state"], "stopped");

    const std::string path = "/api/v1/jobs/" + std::to_string(job);
    const auto info = user.get(path);
    ASSERT_EQ(info.status, 200) << info.body;
    EXPECT_EQ(info.json()["state"], "done");
    EXPECT_EQ(info.json()["model_id"], model);
    EXPECT_EQ(info.json()["name"], "live session " + std::to_string(id) + " (recorded)");
    // The stored run keeps the session's changes, as live.record answered them.
    const nlohmann::json live = info.json().value("live", nlohmann::json());
    ASSERT_TRUE(live.is_object()) << info.body;
    EXPECT_EQ(live["session_id"], id);
    EXPECT_EQ(live["full"], false);
    EXPECT_EQ(live["changes"], data["changes"]);
    const auto history = user.get("/api/v1/jobs?model_id=" + std::to_string(model));
    ASSERT_EQ(history.status, 200) << history.body;
    bool listed = false;
    for (const auto& run : history.json()) listed = listed || run["id"] == job;
    EXPECT_TRUE(listed) << history.body;

    const auto results = user.get(path + "/results");
    ASSERT_EQ(results.status, 200) << results.body;
    const nlohmann::json table = results.json();
    ASSERT_EQ(table["time"].size(), 4u) << results.body;
    ASSERT_EQ(table["variables"].size(), 1u);
    EXPECT_EQ(table["variables"][0]["name"], kStepOut);
    const nlohmann::json& values = table["variables"][0]["data"];
    ASSERT_EQ(values.size(), 4u);
    for (std::size_t i = 1; i < values.size(); ++i) {
        const double t = table["time"][i].get<double>();
        EXPECT_EQ(values[i].get<double>(), t > changedAt + 1e-12 ? 0.9 : 0.2) << "at " << t;
    }
    EXPECT_NEAR(table["time"][3].get<double>(), 16 * kServoStep, 1e-12);
}

TEST_F(LiveSessions, AnotherUserCanNeitherRecordASessionNorReadItsRecording)
{
    HttpClient owner = loggedInAs(*server, "recowner");
    HttpClient snoop = loggedInAs(*server, "recsnoop");
    WsClient ws = socketOf(owner);
    WsClient other = socketOf(snoop);
    const std::int64_t id = start(ws, servoOf(owner), {{"paused", true}});
    ASSERT_GT(id, 0);
    EXPECT_EQ(errorCode(other.call("live.record", {{"session_id", id}})), "not_found");
    const nlohmann::json recorded = ws.call("live.record", {{"session_id", id}});
    ASSERT_EQ(recorded.value("type", ""), "reply") << recorded.dump();
    const std::string path = "/api/v1/jobs/" + std::to_string(recorded["data"]["job_id"].get<std::int64_t>());
    EXPECT_EQ(snoop.get(path).status, 404);
    EXPECT_EQ(snoop.get(path + "/results").status, 404);
    EXPECT_EQ(owner.get(path + "/results").status, 200);
    EXPECT_EQ(ws.call("live.stop", {{"session_id", id}})["data"]["state"], "stopped");
}

TEST_F(LiveSessions, BinaryFramesCarryTheSameStampAndValues)
{
    HttpClient user = loggedInAs(*server, "binary");
    WsClient ws = socketOf(user);
    const std::int64_t id = start(ws, servoOf(user), {{"paused", true}, {"frames", "binary"}});
    ASSERT_GT(id, 0);
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 20}}).value("type", ""), "reply");
    const nlohmann::json frame = until(ws, [](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > 0; });
    ASSERT_TRUE(frame.is_object());
    ASSERT_FALSE(ws.binaryHeaders.empty());
    const nlohmann::json& header = ws.binaryHeaders.back();
    EXPECT_EQ(header["type"], "event.live.frame");
    EXPECT_EQ(header["session_id"], id);
    EXPECT_EQ(header["time_samples"], 1);
    EXPECT_NEAR(frame["model_time"].get<double>(), 20 * kServoStep, 1e-12);
    EXPECT_EQ(frame["time"], nlohmann::json::array({frame["model_time"]}));
    EXPECT_EQ(stepOut(frame), 0.2);
}

TEST_F(LiveSessions, ALateSubscriberGetsTheKeptSamplesThenTheLiveOnes)
{
    HttpClient user = loggedInAs(*server, "watcher");
    WsClient ws = socketOf(user);
    const std::int64_t id = start(ws, servoOf(user), {{"paused", true}});
    ASSERT_GT(id, 0);
    for (int steps : {10, 10, 10}) {
        ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", steps}}).value("type", ""), "reply");
        ASSERT_TRUE(until(ws, [](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > 0; }).is_object());
        ws.events.clear();
    }
    // Another socket of the owner's: the first frame holds every frame so far.
    WsClient late = socketOf(user);
    const nlohmann::json subscribed = late.call("live.subscribe", {{"session_id", id}});
    ASSERT_EQ(subscribed.value("type", ""), "reply") << subscribed.dump();
    EXPECT_EQ(subscribed["data"]["state"], "paused");
    nlohmann::json frame = until(late, isFrame);
    ASSERT_TRUE(frame.is_object());
    ASSERT_EQ(frame["time"].size(), 4u) << frame.dump();   // the start, and after each live.step
    EXPECT_EQ(frame["time"][0].get<double>(), 0.0);
    EXPECT_NEAR(frame["time"][3].get<double>(), 30 * kServoStep, 1e-12);
    EXPECT_EQ(frame["variables"][kStepOut].size(), 4u);
    EXPECT_NEAR(frame["model_time"].get<double>(), 30 * kServoStep, 1e-12);
    // Then what the owner does shows on both.
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 5}}).value("type", ""), "reply");
    frame = until(late, isFrame);
    ASSERT_TRUE(frame.is_object());
    EXPECT_NEAR(frame["model_time"].get<double>(), 35 * kServoStep, 1e-12);
    EXPECT_EQ(frame["time"].size(), 1u);
    // The watcher leaves; the session goes on. The owner leaves; the session ends.
    late = socketOf(user);
    EXPECT_EQ(late.call("live.subscribe", {{"session_id", id}})["data"]["state"], "paused");
    ASSERT_EQ(ws.call("live.resume", {{"session_id", id}})["data"]["state"], "running");
    ws = WsClient(server->port(), user.token());
    const nlohmann::json closed = until(late, [](const nlohmann::json& e) { return isState(e, "stopped"); });
    ASSERT_TRUE(closed.is_object());
    EXPECT_EQ(closed["reason"], "closed");
}

TEST_F(LiveSessions, AParameterOnlyARestartAppliesIsRefusedWithRestartRequired)
{
    HttpClient user = loggedInAs(*server, "restart");
    WsClient ws = socketOf(user);
    const std::int64_t id = start(ws, servoOf(user), {{"paused", true}});
    ASSERT_GT(id, 0);
    const nlohmann::json mass = ws.call("live.set", {{"session_id", id}, {"name", "Mass.m"}, {"value", 20}});
    EXPECT_EQ(errorCode(mass), "restart_required") << mass.dump();
    EXPECT_NE(errorMessage(mass).find("Mass.m"), std::string::npos) << mass.dump();
    EXPECT_EQ(errorCode(ws.call("live.set", {{"session_id", id}, {"name", "Nobody.k"}, {"value", 1}})),
              "invalid_parameter");
    // The session goes on.
    const nlohmann::json stepped = ws.call("live.step", {{"session_id", id}, {"steps", 5}});
    EXPECT_EQ(stepped["data"]["state"], "paused") << stepped.dump();
    const nlohmann::json frame = until(ws, [](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > 0; });
    ASSERT_TRUE(frame.is_object());
    EXPECT_NEAR(frame["model_time"].get<double>(), 5 * kServoStep, 1e-12);
}

TEST_F(LiveSessions, PauseStepAndResume)
{
    HttpClient user = loggedInAs(*server, "stepper");
    WsClient ws = socketOf(user);
    const std::int64_t id = start(ws, servoOf(user), {{"speed", 0.2}});
    ASSERT_GT(id, 0);
    ASSERT_TRUE(until(ws, [](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > 0; }).is_object());
    EXPECT_EQ(errorCode(ws.call("live.step", {{"session_id", id}, {"steps", 10}})), "conflict");
    const nlohmann::json paused = ws.call("live.pause", {{"session_id", id}});
    ASSERT_EQ(paused["data"]["state"], "paused") << paused.dump();
    std::vector<nlohmann::json> seen;
    ASSERT_TRUE(until(ws, [](const nlohmann::json& e) { return isState(e, "paused"); }, &seen).is_object());
    // Frames of the tick that was running when the pause came; none after a while.
    std::this_thread::sleep_for(300ms);
    ws.events.clear();
    ASSERT_EQ(ws.call("ping").value("type", ""), "reply");
    double pausedAt = -1;
    for (const auto& e : ws.events) EXPECT_FALSE(isFrame(e)) << "a frame while paused: " << e.dump();
    for (const auto& e : seen)
        if (isFrame(e)) pausedAt = std::max(pausedAt, e["model_time"].get<double>());
    const nlohmann::json again = ws.call("live.pause", {{"session_id", id}});
    const double at = again["data"]["model_time"].get<double>();
    EXPECT_GE(at, pausedAt);

    EXPECT_EQ(errorCode(ws.call("live.step", {{"session_id", id}, {"steps", 1000001}})), "schema_violation");
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 100}})["data"]["state"], "paused");
    const nlohmann::json frame = until(ws, [at](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > at; });
    ASSERT_TRUE(frame.is_object());
    EXPECT_NEAR(frame["model_time"].get<double>(), at + 100 * kServoStep, 1e-9);

    const nlohmann::json resumed = ws.call("live.resume", {{"session_id", id}});
    EXPECT_EQ(resumed["data"]["state"], "running") << resumed.dump();
    EXPECT_TRUE(until(ws, [](const nlohmann::json& e) { return isState(e, "running"); }).is_object());
    const double resumedAt = frame["model_time"].get<double>();
    EXPECT_TRUE(until(ws, [resumedAt](const nlohmann::json& e) {
        return isFrame(e) && e["model_time"].get<double>() > resumedAt;
    }).is_object());
}

TEST_F(LiveSessions, AtMaxTheRunReachesItsStopTimeAndEnds)
{
    HttpClient user = loggedInAs(*server, "fast");
    WsClient ws = socketOf(user);
    const std::int64_t id = start(ws, servoOf(user), {{"speed", "max"}});
    ASSERT_GT(id, 0);
    std::vector<nlohmann::json> seen;
    const nlohmann::json stopped = until(ws, [](const nlohmann::json& e) { return isState(e, "stopped"); }, &seen, 60000);
    ASSERT_TRUE(stopped.is_object());
    EXPECT_EQ(stopped["reason"], "finished");
    EXPECT_EQ(stopped["speed"], "max");
    EXPECT_NEAR(stopped["model_time"].get<double>(), 3.0, 1e-9);
    // The last frame shows the end, and the value the step reached (y_0 + y_A).
    nlohmann::json lastFrame;
    for (const auto& e : seen)
        if (isFrame(e)) lastFrame = e;
    ASSERT_TRUE(lastFrame.is_object());
    EXPECT_NEAR(lastFrame["model_time"].get<double>(), 3.0, 1e-9);
    EXPECT_NEAR(stepOut(lastFrame), 0.7, 1e-12);
}

TEST_F(LiveSessions, AThirdSessionOfAUserIsRefusedNamingTheLimitsFlag)
{
    HttpClient user = loggedInAs(*server, "limited");
    WsClient ws = socketOf(user);
    const std::int64_t model = servoOf(user);
    const std::int64_t first = start(ws, model, {{"paused", true}});
    ASSERT_GT(start(ws, model, {{"paused", true}}), 0);
    const nlohmann::json third = ws.call("live.start", {{"model_id", model}, {"paused", true}});
    EXPECT_EQ(errorCode(third), "rate_limited") << third.dump();
    EXPECT_NE(errorMessage(third).find("--max-live-sessions-per-user"), std::string::npos) << third.dump();
    // Once one stops, there is room again.
    ASSERT_EQ(ws.call("live.stop", {{"session_id", first}})["data"]["state"], "stopped");
    EXPECT_GT(start(ws, model, {{"paused", true}}), 0);
}

// An animated diagram needs a value of every node: a session streams every variable it names,
// however many the model has, up to the limit (a job stream shows 16 at most).
TEST_F(LiveSessions, EveryNamedVariableIsStreamedAndPastTheLimitTheStartIsRefused)
{
    tlmhub::LoadedModel servo = tlmhub::loadHmfFile(kPositionServo.string());
    ASSERT_TRUE(servo.root) << servo.firstError();
    tlmhub::Result<tlmhub::Simulation> compiled = tlmhub::compile(std::move(servo.root));
    ASSERT_TRUE(compiled) << compiled.status().message();
    // Variables are listed once logged: ten steps do it.
    ASSERT_TRUE(compiled->runSteps(10));
    std::vector<std::string> all;
    for (const tlmhub::LoggedVariable& v : tlmhub::listLoggedVariables(compiled->system())) all.push_back(v.fullName);
    ASSERT_GT(all.size(), 16u);

    HttpClient user = loggedInAs(*server, "animator");
    WsClient ws = socketOf(user);
    const std::int64_t model = servoOf(user);
    const nlohmann::json started = ws.call("live.start", {{"model_id", model}, {"paused", true}, {"variables", all}});
    ASSERT_EQ(started.value("type", ""), "reply") << started.dump();
    EXPECT_EQ(started["data"]["variables"].get<std::vector<std::string>>(), all);
    const std::int64_t id = started["data"]["session_id"].get<std::int64_t>();
    ASSERT_EQ(ws.call("live.step", {{"session_id", id}, {"steps", 10}})["type"], "reply");
    const nlohmann::json frame = until(ws, isFrame);
    ASSERT_TRUE(frame.is_object());
    EXPECT_EQ(frame["variables"].size(), all.size()) << frame.dump();
    ASSERT_EQ(ws.call("live.stop", {{"session_id", id}})["data"]["state"], "stopped");

    std::vector<std::string> tooMany;
    while (tooMany.size() <= 512) tooMany.insert(tooMany.end(), all.begin(), all.end());
    const nlohmann::json refused = ws.call("live.start", {{"model_id", model}, {"variables", tooMany}});
    EXPECT_EQ(errorCode(refused), "limit_exceeded") << refused.dump();
    EXPECT_NE(errorMessage(refused).find("at most 512"), std::string::npos) << refused.dump();
}

TEST_F(LiveSessions, OnlyTheOwnerControlsASessionOnAModelTheyMayRead)
{
    HttpClient owner = loggedInAs(*server, "owner");
    HttpClient intruder = loggedInAs(*server, "intruder");
    WsClient mine = socketOf(owner);
    WsClient theirs = socketOf(intruder);
    const std::int64_t model = servoOf(owner);
    const std::int64_t id = start(mine, model, {{"paused", true}});
    ASSERT_GT(id, 0);
    // Another user's private model is not there for them, nor is the session.
    EXPECT_EQ(errorCode(theirs.call("live.start", {{"model_id", model}})), "not_found");
    for (const char* type : {"live.pause", "live.resume", "live.stop"})
        EXPECT_EQ(errorCode(theirs.call(type, {{"session_id", id}})), "not_found") << type;
    EXPECT_EQ(errorCode(theirs.call("live.set", {{"session_id", id}, {"name", "Step.y_0"}, {"value", 1}})), "not_found");
    EXPECT_EQ(errorCode(theirs.call("live.step", {{"session_id", id}, {"steps", 1}})), "not_found");
    EXPECT_EQ(errorCode(theirs.call("live.speed", {{"session_id", id}, {"speed", 2}})), "not_found");
    // The owner's session is untouched.
    EXPECT_EQ(mine.call("live.step", {{"session_id", id}, {"steps", 1}})["data"]["state"], "paused");
    EXPECT_EQ(errorCode(mine.call("live.start", {{"model_id", 999999}})), "not_found");
    EXPECT_EQ(errorCode(mine.call("live.start", {{"model_id", model}, {"speed", 1000}})), "schema_violation");
    EXPECT_EQ(errorCode(mine.call("live.start", {{"model_id", model}, {"variables", {"Nobody#out#Value"}}})), "bad_request");
}

TEST_F(LiveSessions, LoggingOutEndsTheSocketAndItsSessions)
{
    HttpClient user = loggedInAs(*server, "leaver");
    const std::int64_t model = servoOf(user);
    {
        WsClient ws = socketOf(user);
        ASSERT_GT(start(ws, model, {{"paused", true}}), 0);
        ASSERT_GT(start(ws, model, {{"paused", true}}), 0);
        EXPECT_EQ(user.post("/api/v1/auth/logout", nlohmann::json::object()).status, 204);
        EXPECT_TRUE(until(ws, [](const nlohmann::json&) { return false; }, nullptr, 10000).is_null());
        EXPECT_TRUE(ws.closedByServer());
    }
    // Both places are free again: a new login starts two sessions.
    HttpClient again = loggedInAs(*server, "leaver");
    WsClient ws = socketOf(again);
    for (int started = 0, tries = 0; started < 2 && tries < 100; ++tries) {
        const nlohmann::json reply = ws.call("live.start", {{"model_id", model}, {"paused", true}});
        if (reply.value("type", "") == "reply") {
            ++started;
            continue;
        }
        ASSERT_EQ(errorCode(reply), "rate_limited") << reply.dump();   // the old ones still ending
        std::this_thread::sleep_for(50ms);
        ASSERT_LT(tries, 99) << "the logged-out sessions never ended";
    }
}

TEST_F(LiveSessionLimits, ANodeRefusesASessionPastItsLimitNamingTheFlag)
{
    HttpClient first = loggedInAs(*server, "first");
    HttpClient second = loggedInAs(*server, "second");
    const std::int64_t model = uploadModel(second, kPositionServo, "Servo");
    WsClient a = socketOf(first);
    WsClient b = socketOf(second);
    const std::int64_t id = start(a, uploadModel(first, kPositionServo, "Servo"), {{"paused", true}});
    ASSERT_GT(id, 0);
    const nlohmann::json refused = b.call("live.start", {{"model_id", model}});
    EXPECT_EQ(errorCode(refused), "busy") << refused.dump();
    EXPECT_NE(errorMessage(refused).find("--max-live-sessions"), std::string::npos) << refused.dump();
    ASSERT_EQ(a.call("live.stop", {{"session_id", id}})["data"]["state"], "stopped");
}

TEST_F(LiveSessionLimits, ASessionWhoseOwnerSendsNothingEndsAfterTheIdleTimeout)
{
    HttpClient user = loggedInAs(*server, "idler");
    const std::int64_t model = servoOf(user);
    WsClient ws = socketOf(user);
    const nlohmann::json reply =
        startOnceThePlaceIsFree(ws, {{"model_id", model}, {"paused", true}, {"variables", {kStepOut}}});
    ASSERT_EQ(reply.value("type", ""), "reply") << reply.dump();
    const nlohmann::json stopped = until(ws, [](const nlohmann::json& e) { return isState(e, "stopped"); });
    ASSERT_TRUE(stopped.is_object());
    EXPECT_EQ(stopped["reason"], "idle_timeout");
    EXPECT_NE(stopped.value("message", "").find("--live-idle-timeout"), std::string::npos) << stopped.dump();
    EXPECT_EQ(errorCode(ws.call("live.resume", {{"session_id", reply["data"]["session_id"]}})), "not_found");
}

TEST_F(LiveSessionLimits, ARecordingPastTheLogLimitStopsNamingTheFlagAndTheSessionGoesOn)
{
    HttpClient user = loggedInAs(*server, "longrec");
    const std::int64_t model = servoOf(user);
    WsClient ws = socketOf(user);
    const nlohmann::json reply =
        startOnceThePlaceIsFree(ws, {{"model_id", model}, {"speed", 1.0}, {"variables", {kStepOut}}});
    ASSERT_EQ(reply.value("type", ""), "reply") << reply.dump();
    const std::int64_t id = reply["data"]["session_id"].get<std::int64_t>();
    const nlohmann::json limit = until(ws, [](const nlohmann::json& e) {
        return e.value("type", "") == "event.live.state" && e.value("reason", "") == "record_limit";
    });
    ASSERT_TRUE(limit.is_object()) << "the recording never reached its limit";
    EXPECT_EQ(limit["state"], "running");
    EXPECT_NE(limit.value("message", "").find("--max-log-samples"), std::string::npos) << limit.dump();
    const double at = limit["model_time"].get<double>();
    // The session goes on.
    EXPECT_TRUE(until(ws, [at](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > at; }).is_object());
    const nlohmann::json recorded = ws.call("live.record", {{"session_id", id}});
    ASSERT_EQ(recorded.value("type", ""), "reply") << recorded.dump();
    EXPECT_EQ(recorded["data"]["full"], true);
    EXPECT_EQ(recorded["data"]["samples"], 5);
    const auto results = user.get("/api/v1/jobs/" + std::to_string(recorded["data"]["job_id"].get<std::int64_t>()) + "/results");
    ASSERT_EQ(results.status, 200) << results.body;
    EXPECT_EQ(results.json()["time"].size(), 5u);
    EXPECT_EQ(ws.call("live.stop", {{"session_id", id}})["data"]["state"], "stopped");
}
