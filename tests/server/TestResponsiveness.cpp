// No I/O thread waits for slow work: while a class logs in at once (argon2id, tens of
// milliseconds of CPU each) and running jobs are cancelled, health probes still answer fast.
#include "ServerHarness.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace tlmhub::test {
namespace {

namespace http = boost::beast::http;
using Clock = std::chrono::steady_clock;

constexpr int kStudents = 40;

// Stores the 4000-component bench model (10 MB) and returns its id.
std::int64_t uploadX200(HttpClient& admin)
{
    const auto model = admin.request(http::verb::post, "/api/v1/models?name=x200",
                                     readFile(kSharedDir / "bench-models" / "position-servo-x200.hmf"),
                                     "application/xml");
    EXPECT_EQ(model.status, 201) << model.body;
    return model.status == 201 ? model.json()["id"].get<std::int64_t>() : 0;
}
// VmHWM: the most memory the server process has held resident so far.
long peakResidentKiB(const ServerProcess& server)
{
    std::istringstream status(readFile("/proc/" + std::to_string(server.pid()) + "/status"));
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

constexpr int kMinProbes = 200;
constexpr auto kProbeBound = std::chrono::milliseconds(500);

TEST(Responsiveness, HealthAnswersWhileFortyLogInAndJobsAreCancelled)
{
    // The real cost: the logins must keep the hashing threads busy.
    ServerProcess server(freshTempDir("responsiveness"), {"--password-hash-cost", "interactive"});
    HttpClient admin = loggedInAs(server, "admin");
    // Long runs to cancel while the logins go on.
    std::vector<std::int64_t> jobs;
    for (int i = 0; i < 2; ++i) {
        const auto r = admin.post("/api/v1/jobs", {{"hmf", readFile(kPositionServo)}, {"stop", 500.0}});
        ASSERT_EQ(r.status, 201) << r.body;
        jobs.push_back(r.json()["id"].get<std::int64_t>());
    }

    std::atomic<int> loginsOk{0}, loginsDone{0};
    std::vector<std::thread> students;
    for (int i = 0; i < kStudents; ++i) {
        students.emplace_back([&] {
            HttpClient client(server.port());
            const auto r = client.post("/api/v1/auth/login", {{"username", "admin"}, {"password", kAdminPassword}});
            if (r.status == 200 && r.json().contains("token")) ++loginsOk;
            ++loginsDone;
        });
    }
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        HttpClient client = admin;
        for (std::int64_t job : jobs) client.request(http::verb::delete_, "/api/v1/jobs/" + std::to_string(job));
    });

    // Probe one after the other until every login is answered and enough probes were made.
    HttpClient probe(server.port());
    int probes = 0, slow = 0, failed = 0;
    Clock::duration slowest{};
    while (probes < kMinProbes || loginsDone.load() < kStudents) {
        const auto sent = Clock::now();
        const auto r = probe.get("/api/v1/health");
        const auto took = Clock::now() - sent;
        ++probes;
        if (r.status != 200) ++failed;
        if (took > kProbeBound) ++slow;
        slowest = std::max(slowest, took);
        if (probes > 20000) break;   // the logins never finished: reported below
    }
    for (auto& s : students) s.join();
    canceller.join();

    EXPECT_EQ(loginsOk.load(), kStudents);
    EXPECT_GE(probes, kMinProbes);
    EXPECT_EQ(failed, 0);
    EXPECT_EQ(slow, 0) << "slowest probe: "
                       << std::chrono::duration_cast<std::chrono::milliseconds>(slowest).count() << " ms";
    for (std::int64_t job : jobs)
        EXPECT_EQ(admin.get("/api/v1/jobs/" + std::to_string(job)).json()["state"], "cancelled");
}

// simulate.stop answers without waiting for the job (the socket's strand would otherwise
// stand still until the job has stopped); event.done says when it has.
TEST(Responsiveness, StoppingARunningJobRepliesAtOnceAndEventDoneFollows)
{
    ServerProcess server(freshTempDir("stop-reply"));
    HttpClient admin(server.port());
    const std::string token = admin.login("admin", kAdminPassword);
    const auto model = admin.request(http::verb::post, "/api/v1/models?name=servo", readFile(kPositionServo),
                                     "application/xml");
    ASSERT_EQ(model.status, 201) << model.body;
    WsClient ws(server.port(), token);
    ASSERT_EQ(ws.call("model.open", {{"model_id", model.json()["id"]}})["type"], "reply");
    const auto started = ws.call("simulate.start", {{"stop", 500.0}, {"variables", {"Position_Sensor#out#Value"}}});
    ASSERT_EQ(started["type"], "reply") << started.dump();
    const std::int64_t job = started["data"]["job_id"].get<std::int64_t>();
    auto nextEventOfJob = [&]() {
        for (;;) {
            nlohmann::json e;
            if (!ws.events.empty()) {
                e = ws.events.front();
                ws.events.erase(ws.events.begin());
            } else {
                e = ws.receive(60000);
            }
            if (e.is_null() || e.value("job_id", std::int64_t{-1}) == job) return e;
        }
    };
    for (nlohmann::json e = nextEventOfJob(); e.is_null() || e["type"] != "event.progress"; e = nextEventOfJob())
        ASSERT_FALSE(e.is_null()) << "the job never reported progress";

    const auto stopped = ws.call("simulate.stop", {{"job_id", job}});
    ASSERT_EQ(stopped["type"], "reply") << stopped.dump();
    EXPECT_EQ(stopped["data"]["state"], "cancelling");
    nlohmann::json e = nextEventOfJob();
    while (!e.is_null() && e["type"] != "event.done") e = nextEventOfJob();
    ASSERT_FALSE(e.is_null()) << "no event.done after the stop";
    EXPECT_EQ(e["state"], "cancelled");
}

// simulate.start compiles the model off the connection's strand: a ping sent right after the
// start of a large model (4000 components) is answered first.
TEST(Responsiveness, AJobBeingCompiledDoesNotHoldUpItsConnection)
{
    ServerProcess server(freshTempDir("compile-off-strand"));
    HttpClient admin(server.port());
    const std::string token = admin.login("admin", kAdminPassword);
    const std::int64_t model = uploadX200(admin);
    WsClient ws(server.port(), token);
    // Opening 4000 components takes seconds under the sanitizers, beside other tests.
    ASSERT_EQ(ws.call("model.open", {{"model_id", model}}, 120000)["type"], "reply");
    ws.sendText(R"({"id": 100, "type": "simulate.start"})");
    ws.sendText(R"({"id": 101, "type": "ping"})");
    std::vector<int> replyOrder;
    while (replyOrder.size() < 2) {
        const nlohmann::json m = ws.receive(60000);
        ASSERT_FALSE(m.is_null()) << "no reply within 60 s";
        if (m.value("type", "") == "reply" || m.value("type", "") == "error") replyOrder.push_back(m["id"].get<int>());
    }
    EXPECT_EQ(replyOrder, (std::vector<int>{101, 100}));
}

// model.open parses the stored model off the I/O threads: while more connections than the
// server has I/O threads (4) open a large model (4000 components, 10 MB), no health probe
// waits for an open (the other openers are two more administrators, two connections each:
// one user's third open at once would be refused, AUsersWebSocketModelOpensTakeTheLargeReplySlots);
// and a connection's next messages wait for the open, so an edit sent right behind it
// applies to the model it opened and the replies come in order.
TEST(Responsiveness, OpeningLargeModelsHoldsUpNeitherTheServerNorTheOrderOfMessages)
{
    constexpr int kOtherOpeners = 4;
    ServerProcess server(freshTempDir("open-off-strand"));
    HttpClient admin(server.port());
    const std::string token = admin.login("admin", kAdminPassword);
    const std::int64_t id = uploadX200(admin);
    std::vector<std::string> otherTokens;
    for (const char* name : {"admin2", "admin3"}) {
        const auto r = admin.post("/api/v1/users", {{"username", name}, {"password", testPassword(name)}, {"role", "admin"}});
        ASSERT_EQ(r.status, 201) << r.body;
        HttpClient other(server.port());
        otherTokens.push_back(other.login(name, testPassword(name)));
    }

    const auto began = Clock::now();
    std::atomic<bool> opened{false};
    std::vector<int> replyOrder;
    std::string editReply;
    std::thread opener([&] {
        std::vector<std::unique_ptr<WsClient>> others;
        for (int i = 0; i < kOtherOpeners; ++i) {
            others.push_back(std::make_unique<WsClient>(server.port(), otherTokens[i % otherTokens.size()]));
            others.back()->sendText(R"({"id": 1, "type": "model.open", "model_id": )" + std::to_string(id) + "}");
        }
        WsClient a(server.port(), token);
        a.sendText(R"({"id": 1, "type": "model.open", "model_id": )" + std::to_string(id) + "}");
        a.sendText(R"({"id": 2, "type": "model.settings", "stop": 7})");
        a.sendText(R"({"id": 3, "type": "ping"})");
        while (replyOrder.size() < 3) {
            const nlohmann::json m = a.receive(120000);
            if (m.is_null()) break;
            const std::string type = m.value("type", "");
            if (type != "reply" && type != "error") continue;
            replyOrder.push_back(m["id"].get<int>());
            if (m["id"] == 2) editReply = m.dump();
        }
        for (auto& other : others) EXPECT_EQ(other->receive(120000)["type"], "reply");
        opened = true;
    });
    HttpClient probe(server.port());
    int probes = 0;
    Clock::duration slowest{};
    while (!opened.load()) {
        const auto sent = Clock::now();
        EXPECT_EQ(probe.get("/api/v1/health").status, 200);
        const auto took = Clock::now() - sent;
        ++probes;
        slowest = std::max(slowest, took);
    }
    opener.join();
    EXPECT_EQ(replyOrder, (std::vector<int>{1, 2, 3}));
    EXPECT_NE(editReply.find("\"reply\""), std::string::npos) << "the edit applied to the opened model: " << editReply;
    EXPECT_GT(probes, 0);
    // An open on an I/O thread holds its probes for most of the time the opens take (1.4 s
    // of about 3 s in Release); off them, a probe waits only for a share of the CPU. Relative,
    // because the opens take a minute under the sanitizers.
    const auto opening = Clock::now() - began;
    EXPECT_LT(slowest * 4, opening) << "slowest probe of " << probes << ": "
                                    << std::chrono::duration_cast<std::chrono::milliseconds>(slowest).count()
                                    << " ms while the opens took "
                                    << std::chrono::duration_cast<std::chrono::milliseconds>(opening).count() << " ms";
}

// Every editor message but ping runs on the request pool, never on an I/O thread (issue 37
// H1: a chain of system parameters evaluated on the I/O threads held /health for everyone).
// With a single I/O thread, health probes run all through a burst of one connection's edits
// and whole-model replies (1000 components each). On the I/O thread a probe waits for the
// message being worked on, about one reply's time; off it, for a share of the CPU.
TEST(Responsiveness, EditorWorkLeavesTheOnlyIoThreadFree)
{
    constexpr int kRounds = 8;
    // The replies (about 1.5 MB each) wait for this client's reading: room for all of them.
    ServerProcess server(freshTempDir("edits-off-io"), {"--io-threads", "1", "--max-ws-queue-bytes", "268435456"});
    HttpClient admin(server.port());
    const std::string token = admin.login("admin", kAdminPassword);
    const auto model = admin.request(http::verb::post, "/api/v1/models?name=x50",
                                     readFile(kSharedDir / "bench-models" / "position-servo-x50.hmf"),
                                     "application/xml");
    ASSERT_EQ(model.status, 201) << model.body;
    WsClient ws(server.port(), token);
    ASSERT_EQ(ws.call("model.open", {{"model_id", model.json()["id"]}}, 120000)["type"], "reply");

    std::atomic<bool> burstDone{false};
    int failed = 0;
    std::vector<Clock::duration> probeTimes;
    std::thread prober([&] {
        HttpClient probe(server.port());
        while (!burstDone.load()) {
            const auto sent = Clock::now();
            if (probe.get("/api/v1/health").status != 200) ++failed;
            probeTimes.push_back(Clock::now() - sent);
        }
    });
    const auto began = Clock::now();
    // Each round a level of the chain aN = a(N-1) + b(N-1), bN = a(N-1) - b(N-1), and the model.
    ws.sendText(R"({"id": 1, "type": "sysparam.set", "name": "a0", "value": 1})");
    ws.sendText(R"({"id": 2, "type": "sysparam.set", "name": "b0", "value": 1})");
    int id = 2;
    for (int level = 1; level <= kRounds; ++level) {
        const std::string a = "a" + std::to_string(level - 1), b = "b" + std::to_string(level - 1);
        ws.sendText(nlohmann::json{{"id", ++id}, {"type", "sysparam.set"}, {"name", "a" + std::to_string(level)},
                                   {"value", a + "+" + b}}.dump());
        ws.sendText(nlohmann::json{{"id", ++id}, {"type", "sysparam.set"}, {"name", "b" + std::to_string(level)},
                                   {"value", a + "-" + b}}.dump());
        ws.sendText(nlohmann::json{{"id", ++id}, {"type", "model.get"}}.dump());
    }
    nlohmann::json last;
    for (int replies = 0; replies < id;) {
        const nlohmann::json m = ws.receive(120000);
        if (m.is_null()) break;
        const std::string type = m.value("type", "");
        if (type == "reply" || type == "error") {
            ++replies;
            EXPECT_EQ(type, "reply") << m.dump(-1).substr(0, 300);
            last = m;
        }
    }
    const auto perReply = (Clock::now() - began) / kRounds;
    burstDone = true;
    prober.join();
    EXPECT_EQ(last["id"], id) << "every reply, in the order of the messages";
    EXPECT_EQ(failed, 0);
    ASSERT_GT(probeTimes.size(), std::size_t{kRounds});
    // On the I/O thread each round's model.get would hold a probe for most of a round, so at
    // least kRounds probes would be slow. The kRounds/2-th slowest is compared, not the
    // slowest: one probe may lose the CPU to a neighbouring test on a 2-core runner (33 ms once).
    // Relative, because the burst takes ten times longer under the sanitizers.
    std::sort(probeTimes.begin(), probeTimes.end(), std::greater<>());
    const auto fourthSlowest = probeTimes[kRounds / 2 - 1];
    const auto ms = [](Clock::duration d) { return std::chrono::duration_cast<std::chrono::milliseconds>(d).count(); };
    const std::string figures = std::to_string(probeTimes.size()) + " health probes: slowest " +
                                std::to_string(ms(probeTimes.front())) + " ms, 4th slowest " +
                                std::to_string(ms(fourthSlowest)) + " ms; a round of the burst " +
                                std::to_string(ms(perReply)) + " ms";
    std::cout << figures << "\n";
    EXPECT_LT(fourthSlowest * 4, perReply) << figures;
}

// A teacher's solution run that would go on for a minute (the check runs' wall limit) holds
// the server's only check thread. Meanwhile an FMU export is built (exports do not share the
// labs' capacity, issue 37 M2), and SIGTERM ends the server within its grace (4 s; the bound is
// 5 s) whatever a request is doing. Before, the stop waited for the run.
TEST(Responsiveness, ACheckRunHoldsUpNeitherAnFmuExportNorSigterm)
{
    ServerProcess server(freshTempDir("sigterm-busy"), {"--max-steps", "100000000000", "--check-threads", "1"});
    HttpClient admin = loggedInAs(server, "admin");
    std::string endless = readFile(kPositionServo);
    const auto stop = endless.find(R"(stop="3")");
    ASSERT_NE(stop, std::string::npos);
    endless.replace(stop, 8, R"(stop="1e6")");
    const auto solution = admin.request(http::verb::post, "/api/v1/models?name=endless", endless, "application/xml");
    ASSERT_EQ(solution.status, 201) << solution.body;
    const std::int64_t templateId = uploadModel(admin, kPositionServo, "template");
    const std::int64_t exported = uploadModel(admin, kFmuGain, "FmuGain");
    const auto created = admin.post("/api/v1/classes", {{"name", "Shutdown"}});
    ASSERT_EQ(created.status, 201) << created.body;

    std::atomic<bool> creatorAnswered{false};
    std::thread creator([&, client = admin]() mutable {
        // Ends without a reply when the server goes (the client throws): what it returns does
        // not matter.
        try {
            client.post("/api/v1/classes/" + std::to_string(created.json()["id"].get<std::int64_t>()) + "/assignments",
                        {{"title", "Endless"},
                         {"template_model_id", templateId},
                         {"solution_model_id", solution.json()["id"]},
                         {"edit_mode", "parameters"},
                         {"parameters", nlohmann::json::array()}});
        } catch (const std::exception&) {
        }
        creatorAnswered = true;
    });
    // The solution's run starts once the request is read; it then runs for 60 s.
    std::this_thread::sleep_for(std::chrono::seconds(2));
    const auto fmu = admin.get("/api/v1/models/" + std::to_string(exported) + "/fmu");
    EXPECT_EQ(fmu.status, 200) << fmu.body.substr(0, 300);
    EXPECT_EQ(fmu.body.rfind("PK", 0), 0u) << "a zip archive";
    EXPECT_FALSE(creatorAnswered.load()) << "the check run was still going when the FMU came";
    const auto began = Clock::now();
    const std::optional<int> status = server.terminateWithin(std::chrono::seconds(30));
    const auto took = Clock::now() - began;
    if (!status) server.kill9();
    creator.join();
    ASSERT_TRUE(status.has_value()) << "still running 30 s after SIGTERM";
    // Status 1: the grace ran out with the run still going (an orderly stop exits 0).
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 1) << "wait status " << *status;
    std::cout << "exited " << std::chrono::duration_cast<std::chrono::milliseconds>(took).count()
              << " ms after SIGTERM\n";
}

// Issue 37 L6: eight parallel GET /models/{id} of a large model made another user wait and
// took the server to 1.1 GB. Large replies are built on a pool of their own, at most two of
// one user's at a time: the rest answer 503 with Retry-After, and another user's large reply
// is built meanwhile.
TEST(Responsiveness, AUsersLargeRepliesAreBuiltTwoAtATime)
{
    constexpr int kParallel = 8;
    ServerProcess server(freshTempDir("large-replies"));
    createTestUsers(server, {"bob"});
    HttpClient admin = loggedInAs(server, "admin");
    const std::int64_t x200 = uploadX200(admin);
    HttpClient bob = loggedInAs(server, "bob");
    const std::int64_t small = uploadModel(bob, kPositionServo, "servo");

    std::vector<HttpReply> replies(kParallel);
    std::vector<std::thread> readers;
    for (int i = 0; i < kParallel; ++i)
        readers.emplace_back([&, i, client = admin]() mutable {
            replies[i] = client.get("/api/v1/models/" + std::to_string(x200));
        });
    const auto bobs = bob.get("/api/v1/models/" + std::to_string(small));
    for (auto& t : readers) t.join();

    EXPECT_EQ(bobs.status, 200) << "another user's large reply is not refused";
    int built = 0, refused = 0;
    std::string model;
    for (const HttpReply& r : replies) {
        if (r.status == 200) {
            ++built;
            if (model.empty()) model = r.body;
            EXPECT_EQ(r.body.size(), model.size()) << "every built reply is the whole model";
            EXPECT_FALSE(r.json()["model"]["system"]["components"].empty());
        } else {
            ++refused;
            EXPECT_EQ(r.status, 503) << r.body;
            EXPECT_EQ(r.json()["error"]["code"], "busy");
            EXPECT_EQ(r.headers.count("Retry-After"), 1u);
        }
    }
    EXPECT_GE(built, 2);
    EXPECT_GE(refused, 1) << "eight at once, at most two built at a time";
    // Once they are built, the user's slots are free again.
    EXPECT_EQ(admin.get("/api/v1/models/" + std::to_string(x200)).status, 200);
    std::cout << "server's peak resident memory: " << peakResidentKiB(server) / 1024 << " MiB\n";
}

// The same over the WebSocket: model.open replies with the whole model, so one user's editors
// opening a large model at once take the same two slots (before, each connection's open ran on
// the request pool, as many at once as the user had connections).
TEST(Responsiveness, AUsersWebSocketModelOpensTakeTheLargeReplySlots)
{
    constexpr int kParallel = 8;
    ServerProcess server(freshTempDir("large-ws-opens"));
    createTestUsers(server, {"bob"});
    HttpClient admin(server.port());
    const std::string token = admin.login("admin", kAdminPassword);
    const std::int64_t x200 = uploadX200(admin);
    HttpClient bob(server.port());
    const std::string bobsToken = bob.login("bob", testPassword("bob"));
    const std::int64_t small = uploadModel(bob, kPositionServo, "servo");

    std::vector<WsClient> editors;
    for (int i = 0; i < kParallel; ++i) editors.emplace_back(server.port(), token);
    WsClient bobsEditor(server.port(), bobsToken);
    const nlohmann::json open = {{"id", 1}, {"type", "model.open"}, {"model_id", x200}};
    for (WsClient& editor : editors) editor.sendText(open.dump());
    const nlohmann::json bobs = bobsEditor.call("model.open", {{"model_id", small}}, 120000);

    EXPECT_EQ(bobs["type"], "reply") << "another user's model.open is not refused: " << bobs.dump().substr(0, 300);
    int built = 0, refused = 0;
    for (WsClient& editor : editors) {
        const nlohmann::json answer = editor.receive(120000);
        ASSERT_FALSE(answer.is_null()) << "no answer to model.open";
        if (answer["type"] == "reply") {
            ++built;
            EXPECT_FALSE(answer["data"]["model"]["system"]["components"].empty());
        } else {
            ++refused;
            EXPECT_EQ(answer["error"]["code"], "busy") << answer.dump();
        }
    }
    EXPECT_GE(built, 2);
    EXPECT_GE(refused, 1) << "eight at once, at most two built at a time";
    // The slots are free again, and a refused editor's connection still serves it.
    EXPECT_EQ(editors.back().call("model.open", {{"model_id", x200}}, 120000)["type"], "reply");
    std::cout << "server's peak resident memory: " << peakResidentKiB(server) / 1024 << " MiB\n";
}

} // namespace
} // namespace tlmhub::test
