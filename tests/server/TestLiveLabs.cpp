// Live sessions in a lab (docs/live-sessions.md, "In a lab") through a real server: a teacher
// shares a session with a class whose members watch it read-only, and a student's session on
// an assignment's locked copy changes only the listed values within their bounds. Position
// Servo (3 s, step 1e-4): `Step.y_A` and `GainP.k` may change while it runs.
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>

using namespace tlmhub::test;
namespace fs = std::filesystem;
namespace http = boost::beast::http;

namespace {

// One server for the suite: teachers tina and otto; tina's classes are made per test with
// students sam and sue; bob is otto's student; olga is in no class.
class LiveLabs : public ::testing::Test {
protected:
    // (members, not file-local names: the server tests are compiled in batches)
    static inline const std::string kStepOut = "Step#out#Value";

    static std::string errorCode(const nlohmann::json& reply)
    {
        return reply.value("type", "") == "error" ? reply["error"].value("code", "") : "";
    }
    static bool isReply(const nlohmann::json& reply) { return reply.value("type", "") == "reply"; }
    static bool isFrame(const nlohmann::json& e) { return e.value("type", "") == "event.live.frame"; }
    static bool isStopped(const nlohmann::json& e)
    {
        return e.value("type", "") == "event.live.state" && e.value("state", "") == "stopped";
    }

    static void SetUpTestSuite()
    {
        dataDir = new fs::path(freshTempDir("livelabs"));
        server = new ServerProcess(*dataDir);
        createTestUsers(*server, {"sam", "sue", "bob", "olga"});
        createTestTeachers(*server, {"tina", "otto"});
    }
    static void TearDownTestSuite()
    {
        delete server;
        fs::remove_all(*dataDir);
        delete dataDir;
    }

    static HttpClient as(const std::string& user) { return loggedInAs(*server, user); }
    static WsClient socketOf(HttpClient& user) { return WsClient(server->port(), user.token()); }

    // A class of `teacher`'s with `students` joined; its id.
    static std::int64_t classOf(const std::string& teacher, std::initializer_list<const char*> students)
    {
        const auto created = as(teacher).post("/api/v1/classes", {{"name", teacher + "'s class"}});
        EXPECT_EQ(created.status, 201) << created.body;
        for (const char* student : students) {
            const auto joined = as(student).post("/api/v1/classes/join", {{"code", created.json()["join_code"]}});
            EXPECT_EQ(joined.status, 200) << joined.body;
        }
        return created.json()["id"].get<std::int64_t>();
    }

    static std::int64_t start(WsClient& ws, std::int64_t model, nlohmann::json fields = nlohmann::json::object())
    {
        fields["model_id"] = model;
        fields["variables"] = {kStepOut};
        const nlohmann::json reply = ws.call("live.start", fields);
        EXPECT_TRUE(isReply(reply)) << reply.dump();
        return isReply(reply) ? reply["data"]["session_id"].get<std::int64_t>() : 0;
    }

    // The next event `done` accepts (earlier ones dropped), or null after 15 s without it.
    static nlohmann::json until(WsClient& ws, const std::function<bool(const nlohmann::json&)>& done)
    {
        while (!ws.events.empty()) {
            nlohmann::json e = std::move(ws.events.front());
            ws.events.erase(ws.events.begin());
            if (done(e)) return e;
        }
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
        while (std::chrono::steady_clock::now() < deadline) {
            nlohmann::json e = ws.receive(15000);
            if (e.is_null()) break;
            if (done(e)) return e;
        }
        return nullptr;
    }

    static fs::path* dataDir;
    static ServerProcess* server;
};
fs::path* LiveLabs::dataDir = nullptr;
ServerProcess* LiveLabs::server = nullptr;

} // namespace

TEST_F(LiveLabs, AStudentWatchesASharedSessionReadOnlyUntilItIsUnshared)
{
    const std::int64_t classId = classOf("tina", {"sam"});
    const std::string livePath = "/api/v1/classes/" + std::to_string(classId) + "/live";
    HttpClient tina = as("tina");
    WsClient teacher = socketOf(tina);
    const std::int64_t id = start(teacher, uploadModel(tina, kPositionServo, "ServoDemo"));
    ASSERT_GT(id, 0);
    HttpClient sam = as("sam");
    // Not shared yet: nothing to watch, and the session is not there for a student.
    EXPECT_EQ(sam.get(livePath).json()["sessions"].size(), 0u);
    WsClient student = socketOf(sam);
    EXPECT_EQ(errorCode(student.call("live.subscribe", {{"session_id", id}})), "not_found");
    EXPECT_EQ(errorCode(student.call("live.model", {{"session_id", id}})), "not_found");

    const nlohmann::json shared = teacher.call("live.share", {{"session_id", id}, {"class_id", classId}});
    ASSERT_TRUE(isReply(shared)) << shared.dump();
    EXPECT_EQ(shared["data"]["class_ids"], nlohmann::json::array({classId}));
    const nlohmann::json listed = sam.get(livePath).json()["sessions"];
    ASSERT_EQ(listed.size(), 1u) << listed.dump();
    EXPECT_EQ(listed[0]["session_id"], id);
    EXPECT_EQ(listed[0]["model_name"], "ServoDemo");
    EXPECT_EQ(listed[0]["teacher"]["username"], "tina");
    // The student may not read the teacher's model, but gets what the session runs, to draw it.
    const nlohmann::json drawing = student.call("live.model", {{"session_id", id}});
    ASSERT_TRUE(isReply(drawing)) << drawing.dump();
    EXPECT_EQ(drawing["data"]["model_name"], "ServoDemo");
    EXPECT_EQ(drawing["data"]["variables"], nlohmann::json::array({kStepOut}));
    EXPECT_GT(drawing["data"]["model"]["system"]["components"].size(), 5u);

    // The student gets the kept samples, then frames whose model time goes on.
    const nlohmann::json watched = student.call("live.subscribe", {{"session_id", id}});
    ASSERT_TRUE(isReply(watched)) << watched.dump();
    const nlohmann::json first = until(student, isFrame);
    ASSERT_TRUE(first.is_object());
    const double firstTime = first["model_time"].get<double>();
    const nlohmann::json later =
        until(student, [&](const nlohmann::json& e) { return isFrame(e) && e["model_time"].get<double>() > firstTime; });
    ASSERT_TRUE(later.is_object()) << "no later frame";
    EXPECT_EQ(later["session_id"], id);
    EXPECT_TRUE(later["variables"].contains(kStepOut));

    // Every control of a watcher is refused as for anyone but the owner.
    EXPECT_EQ(errorCode(student.call("live.set", {{"session_id", id}, {"name", "Step.y_A"}, {"value", 1}})), "not_found");
    for (const char* type : {"live.pause", "live.resume", "live.stop", "live.record"})
        EXPECT_EQ(errorCode(student.call(type, {{"session_id", id}})), "not_found") << type;
    EXPECT_EQ(errorCode(student.call("live.step", {{"session_id", id}, {"steps", 1}})), "not_found");
    EXPECT_EQ(errorCode(student.call("live.speed", {{"session_id", id}, {"speed", 2}})), "not_found");
    EXPECT_EQ(errorCode(student.call("live.share", {{"session_id", id}, {"class_id", classId}})), "not_found");
    EXPECT_EQ(errorCode(student.call("live.unshare", {{"session_id", id}, {"class_id", classId}})), "not_found");
    // ... and the session runs on for its owner.
    EXPECT_EQ(teacher.call("live.pause", {{"session_id", id}})["data"]["state"], "paused");

    // Unshared: the student's watch ends, the session goes on, and it is gone for them.
    const nlohmann::json unshared = teacher.call("live.unshare", {{"session_id", id}, {"class_id", classId}});
    ASSERT_TRUE(isReply(unshared)) << unshared.dump();
    EXPECT_EQ(unshared["data"]["class_ids"].size(), 0u);
    const nlohmann::json ended = until(student, isStopped);
    ASSERT_TRUE(ended.is_object()) << "the watcher was not told";
    EXPECT_EQ(ended["reason"], "unshared");
    EXPECT_EQ(teacher.call("live.resume", {{"session_id", id}})["data"]["state"], "running");
    EXPECT_EQ(errorCode(student.call("live.subscribe", {{"session_id", id}})), "not_found");
    EXPECT_EQ(sam.get(livePath).json()["sessions"].size(), 0u);
}

TEST_F(LiveLabs, StoppingASharedSessionEndsEveryWatchWithItsReason)
{
    const std::int64_t classId = classOf("tina", {"sam", "sue"});
    HttpClient tina = as("tina");
    WsClient teacher = socketOf(tina);
    const std::int64_t id = start(teacher, uploadModel(tina, kPositionServo, "ServoDemo"), {{"paused", true}});
    ASSERT_GT(id, 0);
    ASSERT_TRUE(isReply(teacher.call("live.share", {{"session_id", id}, {"class_id", classId}})));
    HttpClient sue = as("sue");
    WsClient student = socketOf(sue);
    ASSERT_TRUE(isReply(student.call("live.subscribe", {{"session_id", id}})));
    // The teacher's second window watches too (as the owner's).
    WsClient secondWindow = socketOf(tina);
    ASSERT_TRUE(isReply(secondWindow.call("live.subscribe", {{"session_id", id}})));
    ASSERT_TRUE(isReply(teacher.call("live.stop", {{"session_id", id}})));
    for (WsClient* ws : {&student, &secondWindow}) {
        const nlohmann::json ended = until(*ws, isStopped);
        ASSERT_TRUE(ended.is_object());
        EXPECT_EQ(ended["reason"], "requested");
    }
    EXPECT_EQ(sue.get("/api/v1/classes/" + std::to_string(classId) + "/live").json()["sessions"].size(), 0u);
    EXPECT_EQ(errorCode(student.call("live.subscribe", {{"session_id", id}})), "not_found");
}

TEST_F(LiveLabs, OnlyTheClassesMembersWatchAndOnlyItsTeacherShares)
{
    const std::int64_t classId = classOf("tina", {"sam"});
    const std::int64_t othersClass = classOf("otto", {"bob"});
    HttpClient tina = as("tina");
    WsClient teacher = socketOf(tina);
    const std::int64_t id = start(teacher, uploadModel(tina, kPositionServo, "ServoDemo"), {{"paused", true}});
    ASSERT_GT(id, 0);
    ASSERT_TRUE(isReply(teacher.call("live.share", {{"session_id", id}, {"class_id", classId}})));
    // A user in no class, and a student of another class: the session is not there for them.
    HttpClient olga = as("olga");
    HttpClient bob = as("bob");
    for (HttpClient* stranger : {&olga, &bob}) {
        WsClient ws = socketOf(*stranger);
        EXPECT_EQ(errorCode(ws.call("live.subscribe", {{"session_id", id}})), "not_found");
        EXPECT_EQ(errorCode(ws.call("live.model", {{"session_id", id}})), "not_found");
        EXPECT_EQ(stranger->get("/api/v1/classes/" + std::to_string(classId) + "/live").status, 404);
    }
    EXPECT_EQ(bob.get("/api/v1/classes/" + std::to_string(othersClass) + "/live").json()["sessions"].size(), 0u);
    // A class the teacher does not teach is not there for her.
    EXPECT_EQ(errorCode(teacher.call("live.share", {{"session_id", id}, {"class_id", othersClass}})), "not_found");
    // A student shares nothing with their class, even a session of their own.
    HttpClient sam = as("sam");
    WsClient student = socketOf(sam);
    const std::int64_t own = start(student, uploadModel(sam, kPositionServo, "Mine"), {{"paused", true}});
    ASSERT_GT(own, 0);
    EXPECT_EQ(errorCode(student.call("live.share", {{"session_id", own}, {"class_id", classId}})), "forbidden");
    // An archived class is shared with no more.
    ASSERT_EQ(tina.request(http::verb::patch, "/api/v1/classes/" + std::to_string(classId), R"({"archived": true})").status,
              200);
    EXPECT_EQ(errorCode(teacher.call("live.share", {{"session_id", id}, {"class_id", classId}})), "archived");
}

TEST_F(LiveLabs, AStudentsSessionOnALockedCopyChangesOnlyTheListedValuesWithinBounds)
{
    const std::int64_t classId = classOf("tina", {"sam"});
    HttpClient tina = as("tina");
    const std::int64_t templateId = uploadModel(tina, kPositionServo, "template");
    const auto assignment = tina.post("/api/v1/classes/" + std::to_string(classId) + "/assignments",
                                      {{"title", "Tune the servo"},
                                       {"template_model_id", templateId},
                                       {"solution_model_id", templateId},
                                       {"edit_mode", "parameters"},
                                       {"parameters", {{{"name", "GainP.k"}, {"min", 0}, {"max", 0.1}}}}});
    ASSERT_EQ(assignment.status, 201) << assignment.body;
    HttpClient sam = as("sam");
    const auto opened =
        sam.post("/api/v1/assignments/" + std::to_string(assignment.json()["id"].get<std::int64_t>()) + "/open",
                 nlohmann::json::object());
    ASSERT_EQ(opened.status, 201) << opened.body;
    const std::int64_t copy = opened.json()["copy"]["model_id"].get<std::int64_t>();

    WsClient ws = socketOf(sam);
    const nlohmann::json started = ws.call("live.start", {{"model_id", copy}, {"paused", true}, {"variables", {kStepOut}}});
    ASSERT_TRUE(isReply(started)) << started.dump();
    const std::int64_t id = started["data"]["session_id"].get<std::int64_t>();
    // Only what the assignment lists, with its bounds.
    const nlohmann::json values = started["data"]["live_values"];
    ASSERT_EQ(values.size(), 1u) << values.dump();
    EXPECT_EQ(values[0]["name"], "GainP.k");
    EXPECT_EQ(values[0]["min"], 0);
    EXPECT_EQ(values[0]["max"], 0.1);

    EXPECT_TRUE(isReply(ws.call("live.set", {{"session_id", id}, {"name", "GainP.k"}, {"value", 0.05}})));
    const nlohmann::json tooHigh = ws.call("live.set", {{"session_id", id}, {"name", "GainP.k"}, {"value", 0.5}});
    EXPECT_EQ(errorCode(tooHigh), "locked");
    EXPECT_NE(tooHigh["error"]["message"].get<std::string>().find("GainP.k"), std::string::npos) << tooHigh.dump();
    const nlohmann::json unlisted = ws.call("live.set", {{"session_id", id}, {"name", "Step.y_A"}, {"value", 0.8}});
    EXPECT_EQ(errorCode(unlisted), "locked");
    EXPECT_NE(unlisted["error"]["message"].get<std::string>().find("Step.y_A"), std::string::npos) << unlisted.dump();

    // The teacher's own session of the template changes anything live.
    WsClient teacher = socketOf(tina);
    const std::int64_t free = start(teacher, templateId, {{"paused", true}});
    ASSERT_GT(free, 0);
    EXPECT_TRUE(isReply(teacher.call("live.set", {{"session_id", free}, {"name", "Step.y_A"}, {"value", 0.8}})));

    // The lock is asked on every set: a student removed from the class changes nothing more.
    nlohmann::json samId;
    for (const auto& user : as("admin").get("/api/v1/users").json())
        if (user["username"] == "sam") samId = user["id"];
    const auto removed =
        tina.request(http::verb::delete_, "/api/v1/classes/" + std::to_string(classId) + "/members/" + samId.dump());
    ASSERT_EQ(removed.status, 204) << samId.dump() << " " << removed.body;
    EXPECT_EQ(errorCode(ws.call("live.set", {{"session_id", id}, {"name", "GainP.k"}, {"value", 0.05}})), "locked");
}
