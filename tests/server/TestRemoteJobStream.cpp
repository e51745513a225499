// Following a job that runs on another node (issue 19, scale-out): ContinuingSink's
// de-duplication across restarted streams, and RemoteJobStream against a real tlmhub-server
// as the worker node (locate backed by its REST job state): the relayed frames, concatenated,
// equal the stored result sample for sample, with one event.done.
#include "server/cluster/ContinuingSink.h"
#include "server/cluster/RemoteJobStream.h"

#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include <chrono>
#include <condition_variable>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>

using namespace tlmhub::server;
using namespace tlmhub::test;
using tlmhub::ResultColumn;
using tlmhub::ResultTable;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

const std::string kSecret = "relay-test-secret-0123456789abcdef0123";

// What a subscriber's sink received.
class Received {
public:
    StreamSink sink()
    {
        StreamSink s;
        s.progress = [this](nlohmann::json) {
            std::lock_guard lock(mMutex);
            ++mProgress;
        };
        s.frame = [this](StreamFrame f) {
            std::lock_guard lock(mMutex);
            EXPECT_TRUE(mDones.empty()) << "a frame after event.done";
            mFrames.push_back(std::move(f));
            mChanged.notify_all();
        };
        s.done = [this](nlohmann::json e) {
            std::lock_guard lock(mMutex);
            mDones.push_back(std::move(e));
            mChanged.notify_all();
        };
        return s;
    }
    bool waitForDone(std::chrono::seconds timeout)
    {
        std::unique_lock lock(mMutex);
        return mChanged.wait_for(lock, timeout, [this] { return !mDones.empty(); });
    }
    bool waitForFrame(std::chrono::seconds timeout)
    {
        std::unique_lock lock(mMutex);
        return mChanged.wait_for(lock, timeout, [this] { return !mFrames.empty(); });
    }
    // The frames' samples concatenated per variable ("time" too); every frame in one layout.
    std::map<std::string, std::vector<double>> columns()
    {
        std::lock_guard lock(mMutex);
        std::map<std::string, std::vector<double>> out;
        for (const auto& f : mFrames) {
            EXPECT_EQ(f.layout, mFrames.front().layout) << "one layout for the subscriber";
            for (const auto& p : f.parts) {
                out["time"].insert(out["time"].end(), p->time.begin(), p->time.end());
                for (std::size_t i = 0; i < f.layout->names.size(); ++i)
                    if (i < p->columns.size())
                        out[f.layout->names[i]].insert(out[f.layout->names[i]].end(), p->columns[i].begin(),
                                                       p->columns[i].end());
            }
        }
        return out;
    }
    std::vector<std::string> names()
    {
        std::lock_guard lock(mMutex);
        return mFrames.empty() ? std::vector<std::string>{} : mFrames.front().layout->names;
    }
    std::vector<nlohmann::json> dones()
    {
        std::lock_guard lock(mMutex);
        return mDones;
    }
    std::size_t frameCount()
    {
        std::lock_guard lock(mMutex);
        return mFrames.size();
    }
    int progressCount()
    {
        std::lock_guard lock(mMutex);
        return mProgress;
    }

private:
    std::mutex mMutex;
    std::condition_variable mChanged;
    std::vector<StreamFrame> mFrames;
    std::vector<nlohmann::json> mDones;
    int mProgress = 0;
};

std::vector<double> range(double from, std::size_t count)
{
    std::vector<double> v(count);
    for (std::size_t i = 0; i < count; ++i) v[i] = from + static_cast<double>(i);
    return v;
}

std::vector<double> slice(const std::vector<double>& v, std::size_t from, std::size_t to)
{
    to = std::min(to, v.size());
    return from < to ? std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(from),
                                           v.begin() + static_cast<std::ptrdiff_t>(to))
                     : std::vector<double>{};
}

// A frame of `table`'s time [t0, t1) and, per column, samples [c0, c1) ("y" lags by `lag`).
StreamFrame tableFrame(const ResultTable& table, const std::shared_ptr<const FrameLayout>& layout, std::size_t t0,
                       std::size_t t1, std::size_t lag = 0)
{
    auto p = std::make_shared<FrameSamples>();
    p->time = slice(table.time, t0, t1);
    for (const auto& name : layout->names) {
        const auto* c = table.column(name);
        const std::size_t l = name == "y" ? lag : 0;
        p->columns.push_back(c ? slice(c->data, t0 > l ? t0 - l : 0, t1 > l ? t1 - l : 0) : std::vector<double>{});
    }
    StreamFrame f;
    f.jobId = 7;
    f.layout = layout;
    f.parts.push_back(std::move(p));
    return f;
}

ResultTable smallTable(std::size_t n)
{
    ResultTable t;
    t.time = range(0, n);
    t.columns.push_back(ResultColumn{"x", "", range(100, n)});
    t.columns.push_back(ResultColumn{"y", "", range(200, n)});
    return t;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// --- a real server as the worker node ---

fs::path writeSecret(const fs::path& dir)
{
    const fs::path file = dir / "node-secret";
    std::ofstream(file) << kSecret << "\n";
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
    return file;
}

struct WorkerNode {
    explicit WorkerNode(const std::string& name)
        : dir(freshTempDir(name)), server(dir / "data", {"--node-secret-file", writeSecret(dir).string()}),
          admin(server.port())
    {
        token = admin.login("admin", kAdminPassword);
        servo = uploadModel(admin, kPositionServo, "servo");
    }
    ~WorkerNode() { fs::remove_all(dir); }
    std::string address() const { return "http://127.0.0.1:" + std::to_string(server.port()); }
    // A job of about a second (3 million steps, 5000 samples), or a short one.
    std::int64_t submit(bool longRun)
    {
        const nlohmann::json body = longRun ? nlohmann::json{{"model_id", servo}, {"stop", 300.0}, {"log_samples", 5000}}
                                            : nlohmann::json{{"model_id", servo}, {"stop", 2.0}, {"log_samples", 501}};
        const auto r = admin.post("/api/v1/jobs", body);
        EXPECT_EQ(r.status, 201) << r.body;
        return r.json().value("id", std::int64_t{0});
    }
    void waitUntilFinished(std::int64_t job)
    {
        for (int i = 0; i < 6000; ++i) {
            const std::string state = admin.get("/api/v1/jobs/" + std::to_string(job)).json().value("state", "");
            if (state != "queued" && state != "running") return;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        ADD_FAILURE() << "job " << job << " did not finish";
    }
    // The whole stored result.
    ResultTable stored(std::int64_t job)
    {
        const auto j = admin.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=json").json();
        ResultTable t;
        for (const auto& v : j.at("time")) t.time.push_back(v.get<double>());
        for (const auto& c : j.at("variables")) {
            ResultColumn column{c.at("name").get<std::string>(), "", {}};
            for (const auto& v : c.at("data")) column.data.push_back(v.get<double>());
            t.columns.push_back(std::move(column));
        }
        return t;
    }
    // locate and storedResult from the server's REST API, as the app backs them from the store
    // (the server is the holder while the job runs); no local hub.
    RemoteJobStreamDependencies dependencies()
    {
        RemoteJobStreamDependencies d;
        d.locate = [port = server.port(), token = token, address = address()](std::int64_t job) -> std::optional<JobLocation> {
            HttpClient c(port);
            c.setToken(token);
            const auto r = c.get("/api/v1/jobs/" + std::to_string(job));
            if (r.status == 404) return std::nullopt;
            if (r.status != 200) throw std::runtime_error("job state: " + r.body);
            const auto j = r.json();
            JobLocation where;
            if (!jobStateFromName(j.at("state").get<std::string>(), where.state)) throw std::runtime_error("state");
            if (j.contains("error") && j["error"].is_string()) where.error = j["error"].get<std::string>();
            if (where.state == JobState::Running) where.holderAddress = address;
            return where;
        };
        d.storedResult = [this](std::int64_t job, const std::vector<std::string>& variables) -> std::optional<ResultTable> {
            ResultTable all = stored(job);
            if (variables.empty()) return all;
            ResultTable picked;
            picked.time = all.time;
            for (auto& c : all.columns)
                if (std::find(variables.begin(), variables.end(), c.name) != variables.end())
                    picked.columns.push_back(std::move(c));
            return picked;
        };
        d.subscribeLocally = [](std::int64_t, std::vector<std::string>, double, StreamSink) -> std::uint64_t {
            ADD_FAILURE() << "the job is not held here";
            return 0;
        };
        d.unsubscribeLocally = [](std::uint64_t) {};
        return d;
    }
    fs::path dir;
    ServerProcess server;
    HttpClient admin;
    std::string token;
    std::int64_t servo = 0;
};

NodeSecret secret()
{
    return NodeSecret::fromText(kSecret);
}

// The relayed columns equal the stored ones (those the relay streamed, and time) bit for bit.
void expectRelayedEqualsStored(Received& got, const ResultTable& stored, std::size_t expectedVariables)
{
    const auto relayed = got.columns();
    const auto names = got.names();
    ASSERT_EQ(names.size(), expectedVariables);
    EXPECT_TRUE(sameBits(relayed.at("time"), stored.time)) << relayed.at("time").size() << " vs " << stored.time.size();
    for (const auto& name : names) {
        const ResultColumn* column = stored.column(name);
        ASSERT_NE(column, nullptr) << name;
        ASSERT_EQ(relayed.count(name), 1u) << name;
        EXPECT_TRUE(sameBits(relayed.at(name), column->data)) << name << ": " << relayed.at(name).size() << " vs "
                                                               << column->data.size();
    }
}

} // namespace

// --- ContinuingSink ---

TEST(ContinuingSink, ARestartedStreamDeliversEachSampleOnce)
{
    const ResultTable table = smallTable(20);
    const auto layout = std::make_shared<const FrameLayout>(std::vector<std::string>{"x", "y"});
    Received got;
    ContinuingSink sink(7, {}, got.sink());
    // Stream A: time 0..7, y one sample behind; then it breaks off.
    StreamSink a = sink.newStream();
    a.frame(tableFrame(table, layout, 0, 5, 1));
    a.frame(tableFrame(table, layout, 5, 8, 1));
    // Stream B (the job run again elsewhere) from sample 0, cut differently, y in step; one
    // of its frames is two merged ones.
    StreamSink b = sink.newStream();
    b.frame(tableFrame(table, layout, 0, 3));
    StreamFrame merged = tableFrame(table, layout, 3, 6);
    merged.append(tableFrame(table, layout, 6, 10));
    b.frame(std::move(merged));
    a.frame(tableFrame(table, layout, 8, 12));   // the old stream is quiet now
    b.frame(tableFrame(table, layout, 10, 20));
    b.done({{"type", "event.done"}, {"job_id", 7}, {"state", "done"}});
    b.done({{"type", "event.done"}, {"job_id", 7}, {"state", "done"}});
    a.done({{"type", "event.done"}, {"job_id", 7}, {"state", "failed"}});

    const auto columns = got.columns();
    EXPECT_EQ(columns.at("time"), table.time);
    EXPECT_EQ(columns.at("x"), table.columns[0].data);
    EXPECT_EQ(columns.at("y"), table.columns[1].data);
    ASSERT_EQ(got.dones().size(), 1u);
    EXPECT_EQ(got.dones()[0]["state"], "done");
    EXPECT_TRUE(sink.finished());
    b.frame(tableFrame(table, layout, 0, 20));   // nothing after done
    EXPECT_EQ(got.columns().at("time").size(), 20u);
}

TEST(ContinuingSink, ANewStreamInAnotherLayoutObjectKeepsTheFirstLayout)
{
    const ResultTable table = smallTable(10);
    Received got;
    ContinuingSink sink(7, {}, got.sink());
    sink.newStream().frame(tableFrame(table, std::make_shared<const FrameLayout>(std::vector<std::string>{"x", "y"}), 0, 4));
    // The same names in another order and object (another node resolved them): matched by name.
    sink.newStream().frame(
        tableFrame(table, std::make_shared<const FrameLayout>(std::vector<std::string>{"y", "x"}), 0, 10));
    const auto columns = got.columns();
    EXPECT_EQ(got.names(), (std::vector<std::string>{"x", "y"}));
    EXPECT_EQ(columns.at("time"), table.time);
    EXPECT_EQ(columns.at("x"), table.columns[0].data);
    EXPECT_EQ(columns.at("y"), table.columns[1].data);
}

TEST(ContinuingSink, TheStoredResultGivesTheRestThenDoneAsTheHubSendsIt)
{
    const ResultTable table = smallTable(30);
    Received got;
    ContinuingSink sink(7, {}, got.sink());
    sink.newStream().frame(tableFrame(table, std::make_shared<const FrameLayout>(std::vector<std::string>{"y"}), 0, 12, 1));
    sink.finishFromTable(&table, JobState::Done, "");
    sink.finishFromTable(&table, JobState::Done, "");
    const auto columns = got.columns();
    EXPECT_EQ(columns.at("time"), table.time);
    EXPECT_EQ(columns.at("y"), table.columns[1].data);
    EXPECT_EQ(columns.count("x"), 0u) << "the subscriber's layout stays";
    ASSERT_EQ(got.dones().size(), 1u);
    EXPECT_EQ(got.dones()[0], (nlohmann::json{{"type", "event.done"}, {"job_id", 7}, {"state", "done"}}));
}

TEST(ContinuingSink, WithoutAFrameTheStoredResultsVariablesAreResolvedAsTheHubDoes)
{
    const ResultTable table = smallTable(5);
    Received wanted;
    ContinuingSink picked(7, {"no#such", "y", "y", "x"}, wanted.sink());
    picked.finishFromTable(&table, JobState::Failed, "it broke");
    EXPECT_EQ(wanted.names(), (std::vector<std::string>{"y", "x"}));
    EXPECT_EQ(wanted.dones().at(0),
              (nlohmann::json{{"type", "event.done"}, {"job_id", 7}, {"state", "failed"}, {"error", "it broke"}}));

    ResultTable wide = smallTable(3);
    for (int i = 0; i < 20; ++i) wide.columns.push_back(ResultColumn{"c" + std::to_string(i), "", range(i, 3)});
    Received all;
    ContinuingSink first(7, {}, all.sink());
    first.finishFromTable(&wide, JobState::Done, "");
    ASSERT_EQ(all.names().size(), StreamHub::kMaxFrameVariables);
    EXPECT_EQ(all.names().front(), "x");

    Received none;
    ContinuingSink noResult(7, {}, none.sink());
    noResult.finishFromTable(nullptr, JobState::Cancelled, "");
    EXPECT_EQ(none.frameCount(), 0u);
    EXPECT_EQ(none.dones().at(0)["state"], "cancelled");
}

// --- RemoteJobStream against a real worker node ---

TEST(RemoteJobStream, ARunningJobOnAnotherNodeIsRelayedSampleForSample)
{
    WorkerNode worker("relay-running");
    const std::int64_t job = worker.submit(true);
    Received got;
    RemoteJobStream stream(job, {}, 120, got.sink(), worker.dependencies(), secret());
    ASSERT_TRUE(got.waitForDone(std::chrono::seconds(120)));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));   // nothing more may come
    EXPECT_TRUE(stream.finished());
    ASSERT_EQ(got.dones().size(), 1u);
    EXPECT_EQ(got.dones()[0], (nlohmann::json{{"type", "event.done"}, {"job_id", job}, {"state", "done"}}));
    EXPECT_GT(got.progressCount(), 0) << "followed live, not only from the stored result";
    EXPECT_GT(got.frameCount(), 1u);
    expectRelayedEqualsStored(got, worker.stored(job), StreamHub::kMaxFrameVariables);
}

TEST(RemoteJobStream, AFinishedJobComesWholeFromTheStoredResult)
{
    WorkerNode worker("relay-finished");
    const std::int64_t job = worker.submit(false);
    worker.waitUntilFinished(job);
    const ResultTable table = worker.stored(job);
    ASSERT_GE(table.columns.size(), 3u);
    const std::vector<std::string> wanted = {table.columns[2].name, "no#such#variable", table.columns[0].name};

    Received got;
    RemoteJobStream stream(job, wanted, 0, got.sink(), worker.dependencies(), secret());
    ASSERT_TRUE(got.waitForDone(std::chrono::seconds(30)));
    EXPECT_EQ(got.names(), (std::vector<std::string>{table.columns[2].name, table.columns[0].name}));
    EXPECT_EQ(got.frameCount(), 1u);
    EXPECT_EQ(got.progressCount(), 0);
    ASSERT_EQ(got.dones().size(), 1u);
    EXPECT_EQ(got.dones()[0], (nlohmann::json{{"type", "event.done"}, {"job_id", job}, {"state", "done"}}));
    expectRelayedEqualsStored(got, table, 2);
}

// The job ran here first (the local hub gave part of it), then its worker died and another
// node runs it again from the start: the relay skips what the subscriber already has. The
// first run's samples come from an identical earlier job (runs are deterministic).
TEST(RemoteJobStream, AJobThatMovesFromThisNodeToAnotherContinuesWhereItWas)
{
    WorkerNode worker("relay-moves");
    const std::int64_t earlier = worker.submit(true);
    worker.waitUntilFinished(earlier);
    const ResultTable firstRun = worker.stored(earlier);
    std::vector<std::string> names;
    for (std::size_t i = 0; i < StreamHub::kMaxFrameVariables; ++i) names.push_back(firstRun.columns[i].name);
    const auto layout = std::make_shared<const FrameLayout>(names);

    std::atomic<bool> here{true};
    std::mutex m;
    std::condition_variable subscribed;
    std::optional<StreamSink> local;
    bool unsubscribed = false;
    std::int64_t job = 0;
    RemoteJobStreamDependencies deps = worker.dependencies();
    auto remoteLocate = deps.locate;
    deps.locate = [&, remoteLocate](std::int64_t id) -> std::optional<JobLocation> {
        if (here) return JobLocation{JobState::Running, "", "", true};
        return remoteLocate(id);
    };
    deps.subscribeLocally = [&](std::int64_t, std::vector<std::string>, double, StreamSink sink) -> std::uint64_t {
        std::lock_guard lock(m);
        local = std::move(sink);
        subscribed.notify_all();
        return 42;
    };
    deps.unsubscribeLocally = [&](std::uint64_t id) {
        EXPECT_EQ(id, 42u);
        std::lock_guard lock(m);
        unsubscribed = true;
    };
    RemoteJobStreamTiming timing;
    timing.holderCheck = std::chrono::milliseconds(100);
    job = worker.submit(true);
    Received got;
    RemoteJobStream stream(job, {}, 120, got.sink(), deps, secret(), timing);
    {
        std::unique_lock lock(m);
        ASSERT_TRUE(subscribed.wait_for(lock, std::chrono::seconds(10), [&] { return local.has_value(); }));
        // A third of the run, as the local hub streamed it before this node lost the job.
        const std::size_t third = firstRun.time.size() / 3;
        local->progress({{"type", "event.progress"}, {"job_id", job}, {"progress", 0.3}});
        local->frame(tableFrame(firstRun, layout, 0, third / 2));
        local->frame(tableFrame(firstRun, layout, third / 2, third));
    }
    here = false;
    ASSERT_TRUE(got.waitForDone(std::chrono::seconds(120)));
    {
        std::lock_guard lock(m);
        EXPECT_TRUE(unsubscribed);
    }
    ASSERT_EQ(got.dones().size(), 1u);
    EXPECT_EQ(got.dones()[0]["state"], "done");
    EXPECT_GT(got.progressCount(), 1) << "the other node's live stream was relayed, not only the stored result";
    expectRelayedEqualsStored(got, worker.stored(job), StreamHub::kMaxFrameVariables);
}

TEST(RemoteJobStream, StopReturnsQuicklyWhileConnectingWaitingOrReading)
{
    auto timeStop = [](RemoteJobStream& stream) {
        const auto t0 = Clock::now();
        stream.stop();
        return std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - t0);
    };
    RemoteJobStreamDependencies base;
    base.storedResult = [](std::int64_t, const std::vector<std::string>&) { return std::optional<ResultTable>(); };
    base.subscribeLocally = [](std::int64_t, std::vector<std::string>, double, StreamSink) { return std::uint64_t{1}; };
    base.unsubscribeLocally = [](std::uint64_t) {};

    // Connecting: a node that accepts the connection (its backlog does) but never answers the
    // upgrade.
    boost::asio::io_context ioc;
    boost::asio::ip::tcp::acceptor silent(ioc, {boost::asio::ip::make_address("127.0.0.1"), 0});
    RemoteJobStreamDependencies connecting = base;
    connecting.locate = [port = silent.local_endpoint().port()](std::int64_t) {
        return std::optional<JobLocation>(JobLocation{JobState::Running, "", "http://127.0.0.1:" + std::to_string(port), false});
    };
    Received a;
    RemoteJobStream upgrading(5, {}, 0, a.sink(), connecting, secret());
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_LT(timeStop(upgrading).count(), 200);
    EXPECT_TRUE(a.dones().empty());

    // Waiting for a queued job to be claimed.
    RemoteJobStreamDependencies queued = base;
    queued.locate = [](std::int64_t) { return std::optional<JobLocation>(JobLocation{}); };
    Received b;
    RemoteJobStreamTiming slowPoll;
    slowPoll.pollPeriod = std::chrono::milliseconds(5000);
    RemoteJobStream waiting(5, {}, 0, b.sink(), queued, secret(), slowPoll);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_LT(timeStop(waiting).count(), 200);

    // Reading a running job's frames from a real node (its holder check made rare).
    WorkerNode worker("relay-stop");
    const std::int64_t job = worker.submit(true);
    Received c;
    RemoteJobStreamTiming rareChecks;
    rareChecks.holderCheck = std::chrono::milliseconds(10000);
    {
        RemoteJobStream reading(job, {}, 30, c.sink(), worker.dependencies(), secret(), rareChecks);
        ASSERT_TRUE(c.waitForFrame(std::chrono::seconds(60)));
        EXPECT_LT(timeStop(reading).count(), 200);
    }
    // The destructor stops too.
    const auto t0 = Clock::now();
    {
        RemoteJobStream dropped(job, {}, 30, c.sink(), worker.dependencies(), secret());
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_LT(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - t0).count(), 50 + 1500);
}
