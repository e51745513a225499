// Live streaming to a WebSocket client that cannot keep up (issue 15): waiting frames of a job
// are merged, so the frames still hold every sample, and when a job's waiting samples would
// pass the socket's byte limit the client gets event.resync instead and reads the stored result.
#include "ServerHarness.h"
#include "server/protocol/SchemaValidator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>

using namespace tlmhub::test;
using tlmhub::server::SchemaValidator;
namespace fs = std::filesystem;

namespace {

// 3 million steps (about a second in Release, 15 s under the sanitizers) logging 50000
// samples of the first 16 variables: about 17 MB of frames at up to 120 frames a second, far
// more than the socket buffers hold (up to 4 MB on the server's side here).
nlohmann::json longRun()
{
    return {{"stop", 300.0}, {"log_samples", 50000}, {"rate", 120}};
}

// Polls the job over REST (not the socket, which the client is leaving unread) until it has
// gone `fraction` of the way or ended.
nlohmann::json waitForProgress(HttpClient& c, std::int64_t job, double fraction, int seconds = 120)
{
    nlohmann::json info;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        info = c.get("/api/v1/jobs/" + std::to_string(job)).json();
        const std::string state = info.value("state", "");
        if ((state != "queued" && state != "running") || info.value("progress", 0.0) >= fraction) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return info;
}

// The job's stored columns by name ("time" too; all when `names` is empty), read from the
// CSV: its "%.17g" numbers give back the stored doubles exactly.
std::map<std::string, std::vector<double>> storedColumns(HttpClient& c, std::int64_t job,
                                                         const std::vector<std::string>& names = {})
{
    std::string list;
    for (const auto& name : names) {
        if (!list.empty()) list += ',';
        for (char ch : name) list += ch == '#' ? std::string("%23") : std::string(1, ch);
    }
    const auto r = c.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv&variables=" + list);
    EXPECT_EQ(r.status, 200) << r.body.substr(0, 300);
    std::istringstream in(r.body);
    std::string line, cell;
    std::getline(in, line);
    std::vector<std::string> header;
    for (std::istringstream fields(line); std::getline(fields, cell, ',');) header.push_back(cell);
    std::map<std::string, std::vector<double>> columns;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        for (std::size_t i = 0; i < header.size() && std::getline(row, cell, ','); ++i)
            columns[header[i]].push_back(std::strtod(cell.c_str(), nullptr));
    }
    return columns;
}

bool bitwiseEqual(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The events of `job` on the socket (those `call` kept first), up to and including event.done.
std::vector<nlohmann::json> eventsUntilDone(WsClient& ws, std::int64_t job)
{
    std::vector<nlohmann::json> out;
    auto keep = [&](nlohmann::json e) {
        if (e.value("job_id", std::int64_t{0}) == job) out.push_back(std::move(e));
        return !out.empty() && out.back()["type"] == "event.done";
    };
    for (auto& e : ws.events)
        if (keep(std::move(e))) return out;
    ws.events.clear();
    for (;;) {
        nlohmann::json e = ws.receive(60000);
        if (e.is_null()) {
            ADD_FAILURE() << "no event.done for job " << job;
            return out;
        }
        if (keep(std::move(e))) return out;
    }
}

// The samples of the events' frames, concatenated per variable ("time" too).
std::map<std::string, std::vector<double>> concatenatedFrames(const std::vector<nlohmann::json>& events)
{
    std::map<std::string, std::vector<double>> streamed;
    for (const auto& e : events) {
        if (e["type"] != "event.frame") continue;
        for (const auto& t : e["time"]) streamed["time"].push_back(t.get<double>());
        for (const auto& [name, values] : e["variables"].items())
            for (const auto& v : values) streamed[name].push_back(v.get<double>());
    }
    return streamed;
}

// Time and the 16 streamed variables, concatenated, equal the job's stored columns bit for bit.
void expectStreamedEqualsStored(HttpClient& admin, std::int64_t job,
                                const std::map<std::string, std::vector<double>>& streamed)
{
    std::vector<std::string> names;
    for (const auto& [name, values] : streamed)
        if (name != "time") names.push_back(name);
    ASSERT_EQ(names.size(), 16u);
    const auto stored = storedColumns(admin, job, names);
    ASSERT_EQ(stored.size(), 17u);
    for (const auto& [name, values] : stored) {
        ASSERT_EQ(streamed.count(name), 1u) << name;
        EXPECT_EQ(streamed.at(name).size(), values.size()) << name;
        EXPECT_TRUE(bitwiseEqual(streamed.at(name), values)) << name;
    }
}

struct ServerWithServo {
    explicit ServerWithServo(const std::string& name, std::vector<std::string> flags)
        : dir(freshTempDir(name)), server(dir, withExamples(std::move(flags))), admin(server.port())
    {
        token = admin.login("admin", kAdminPassword);
        servo = modelIdNamed(admin, "Position Servo");
    }
    ~ServerWithServo() { fs::remove_all(dir); }
    static std::vector<std::string> withExamples(std::vector<std::string> flags)
    {
        flags.insert(flags.end(), {"--examples-dir", kExampleModels.string()});
        return flags;
    }
    fs::path dir;
    ServerProcess server;
    HttpClient admin;
    std::string token;
    std::int64_t servo = 0;
};

} // namespace

// The client stops reading for most of a long run and then reads on: with a queue limit of
// 2 messages its frames merge, and concatenated they equal the stored result bit for bit
// (the old queue dropped the oldest frames instead: thousands of samples were missing). The
// byte limit is raised so that the merged frame never gives way to event.resync.
TEST(Streaming, ASlowReaderGetsEverySampleInMergedFrames)
{
    ServerWithServo s("stream-lossless", {"--max-ws-queue-messages", "2", "--max-ws-queue-bytes", "268435456"});
    WsClient ws(s.server.port(), s.token, 16384);
    ASSERT_EQ(ws.call("model.open", {{"model_id", s.servo}})["type"], "reply");
    const auto started = ws.call("simulate.start", longRun());
    ASSERT_EQ(started["type"], "reply") << started.dump();
    const std::int64_t job = started["data"]["job_id"].get<std::int64_t>();
    waitForProgress(s.admin, job, 0.8);   // meanwhile the socket is not read
    const auto events = eventsUntilDone(ws, job);
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back()["state"], "done") << events.back().dump();

    std::uint64_t seq = 0, merged = 0;
    for (const auto& e : events) {
        ASSERT_NE(e["type"], "event.resync") << "the byte limit is far above the stream";
        if (e["type"] != "event.frame") continue;
        EXPECT_EQ(e["seq"].get<std::uint64_t>(), seq++) << "seq counts the frames sent";
        merged += e["dropped"].get<std::uint64_t>();
        ASSERT_EQ(e["variables"].size(), 16u) << e["variables"].dump().substr(0, 300);
    }
    EXPECT_GT(merged, 0u) << "the client was slow, so frames were merged";
    expectStreamedEqualsStored(s.admin, job, concatenatedFrames(events));
}

// Past the byte limit the waiting samples go, the client gets event.resync (and no more
// frames) for the job, then event.done; the queue never holds more than the limit, the
// connection stays open and the stored result is there to read instead.
TEST(Streaming, PastTheByteLimitTheClientIsToldToReadTheStoredResult)
{
    constexpr std::int64_t kByteLimit = 300000;
    ServerWithServo s("stream-resync", {"--max-ws-queue-bytes", std::to_string(kByteLimit)});
    WsClient ws(s.server.port(), s.token, 16384);
    ASSERT_EQ(ws.call("model.open", {{"model_id", s.servo}})["type"], "reply");
    const auto started = ws.call("simulate.start", longRun());
    ASSERT_EQ(started["type"], "reply") << started.dump();
    const std::int64_t job = started["data"]["job_id"].get<std::int64_t>();
    // The socket is not read while the job runs; the queue's size is sampled meanwhile.
    std::int64_t mostQueued = 0;
    for (int i = 0; i < 6000; ++i) {
        mostQueued = std::max(mostQueued, s.admin.get("/api/v1/stats").json()["websocket_queued_bytes"].get<std::int64_t>());
        const std::string state = s.admin.get("/api/v1/jobs/" + std::to_string(job)).json()["state"].get<std::string>();
        if (state != "queued" && state != "running") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_LE(mostQueued, kByteLimit) << "the queue stays within its byte limit";
    const auto events = eventsUntilDone(ws, job);
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back()["type"], "event.done");
    EXPECT_EQ(events.back()["state"], "done") << events.back().dump();
    std::size_t resync = events.size();
    for (std::size_t i = 0; i < events.size(); ++i)
        if (events[i]["type"] == "event.resync") {
            resync = i;
            break;
        }
    ASSERT_LT(resync, events.size()) << "event.resync for the job";
    for (std::size_t i = resync + 1; i < events.size(); ++i)
        EXPECT_NE(events[i]["type"], "event.frame") << "no frames after event.resync";
    EXPECT_EQ(ws.call("ping")["type"], "reply") << "the connection stays open";
    EXPECT_EQ(storedColumns(s.admin, job, {"Mass#P1#Position"}).at("time").size(), 50000u);
}

// A client that asks for binary frames gets every frame as a binary message (a JSON header
// the schema describes, then float64 columns) carrying exactly the stored samples; a second
// socket streaming the same job as JSON gets the same samples.
TEST(Streaming, BinaryFramesCarryExactlyTheStoredSamples)
{
    ServerWithServo s("stream-binary", {});
    WsClient binary(s.server.port(), s.token);
    ASSERT_EQ(binary.call("model.open", {{"model_id", s.servo}})["type"], "reply");
    const auto started = binary.call("simulate.start", {{"stop", 20.0}, {"log_samples", 20000}, {"frames", "binary"}});
    ASSERT_EQ(started["type"], "reply") << started.dump();
    const auto job = started["data"]["job_id"].get<std::int64_t>();
    WsClient json(s.server.port(), s.token);
    ASSERT_EQ(json.call("log.subscribe", {{"job_id", job}})["type"], "reply");

    const auto binaryEvents = eventsUntilDone(binary, job);
    ASSERT_FALSE(binaryEvents.empty());
    EXPECT_EQ(binaryEvents.back()["state"], "done") << binaryEvents.back().dump();
    const auto frames = std::count_if(binaryEvents.begin(), binaryEvents.end(),
                                      [](const nlohmann::json& e) { return e["type"] == "event.frame"; });
    EXPECT_GT(frames, 0);
    EXPECT_EQ(binary.binaryHeaders.size(), static_cast<std::size_t>(frames)) << "every frame was binary";
    for (const auto& header : binary.binaryHeaders) {
        std::string why;
        EXPECT_TRUE(SchemaValidator::protocol().validate("BinaryFrameHeader", header, why)) << why;
    }

    expectStreamedEqualsStored(s.admin, job, concatenatedFrames(binaryEvents));

    // The JSON subscriber came a little later: its first frame may hold more, but all in all
    // it has the same samples, and no binary message.
    expectStreamedEqualsStored(s.admin, job, concatenatedFrames(eventsUntilDone(json, job)));
    EXPECT_TRUE(json.binaryHeaders.empty());
}

// A run started from the editor computes what the model file does: the job runs a copy of
// the editor's model. The old server saved the editor's model as text and loaded that, and
// the text listed a multiport's connections in another order than the file did (this
// model's pump and valves share one), so the editor's run gave other numbers.
TEST(Streaming, AnEditorsRunComputesWhatItsModelFileDoes)
{
    ServerWithServo s("editor-run", {});
    const std::string name = "Load Sensing System";
    WsClient ws(s.server.port(), s.token);
    ASSERT_EQ(ws.call("model.open", {{"model_id", modelIdNamed(s.admin, name)}})["type"], "reply");
    const auto started = ws.call("simulate.start", {{"log_samples", 200}});
    ASSERT_EQ(started["type"], "reply") << started.dump();
    const auto edited = started["data"]["job_id"].get<std::int64_t>();
    const auto posted = s.admin.post("/api/v1/jobs", {{"hmf", readFile(kExampleModels / (name + ".hmf"))}, {"log_samples", 200}});
    ASSERT_EQ(posted.status, 201) << posted.body;
    const auto fromFile = posted.json()["id"].get<std::int64_t>();
    for (const std::int64_t job : {edited, fromFile})
        ASSERT_EQ(waitForProgress(s.admin, job, 1.0)["state"], "done") << job;

    const auto a = storedColumns(s.admin, edited);
    const auto b = storedColumns(s.admin, fromFile);
    ASSERT_GT(a.size(), 10u);
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [column, values] : a) EXPECT_TRUE(bitwiseEqual(values, b.at(column))) << column;
}
