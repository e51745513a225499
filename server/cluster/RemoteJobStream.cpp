#include "server/cluster/RemoteJobStream.h"

#include "server/jobs/StreamFrameDecoding.h"
#include "server/protocol/UntrustedJson.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http/field.hpp>
#include <boost/beast/websocket.hpp>

#include <algorithm>

namespace tlmhub::server {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = net::ip::tcp;
using Clock = std::chrono::steady_clock;

namespace {

constexpr auto kFirstBackoff = std::chrono::milliseconds(50);
// A frame the worker merged for a slow reader; its queue resyncs past 16 MiB (the default).
constexpr std::size_t kMaxMessageBytes = 64u << 20;
constexpr double kMaxSubscribeRate = 1000;   // the schema's maximum for log.subscribe's rate

// "http://host:port" (or "http://[v6]:port"); false for anything else (https is not spoken).
bool splitAddress(const std::string& address, std::string& host, std::string& port)
{
    const std::string scheme = "http://";
    if (address.rfind(scheme, 0) != 0) return false;
    std::string rest = address.substr(scheme.size());
    while (!rest.empty() && rest.back() == '/') rest.pop_back();
    if (rest.empty()) return false;
    std::size_t colon = std::string::npos;
    if (rest.front() == '[') {
        const auto close = rest.find(']');
        if (close == std::string::npos) return false;
        host = rest.substr(1, close - 1);
        if (close + 1 < rest.size()) {
            if (rest[close + 1] != ':') return false;
            colon = close + 1;
        }
    } else {
        colon = rest.rfind(':');
        host = rest.substr(0, colon);
    }
    port = colon == std::string::npos ? "80" : rest.substr(colon + 1);
    return !host.empty() && !port.empty();
}

// One connection's asynchronous steps, each completed by running its own io_context on the
// stream's thread until the step is done, stop() wakes it, or its deadline passes.
struct Connection {
    explicit Connection(net::io_context& context) : ioc(context), ws(context) {}
    net::io_context& ioc;
    websocket::stream<tcp::socket> ws;
    beast::flat_buffer buffer;

    enum class Wait { Done, Stopped, TimedOut };
    template <typename Stop>
    Wait run(const bool& done, Clock::time_point deadline, Stop stopping)
    {
        while (!done) {
            if (stopping()) return Wait::Stopped;
            if (Clock::now() >= deadline) return Wait::TimedOut;
            if (ioc.stopped()) ioc.restart();
            ioc.run_one_until(deadline);
        }
        return Wait::Done;
    }
    // Ends every operation in progress (their handlers run with operation_aborted).
    void abort()
    {
        beast::error_code ignored;
        ws.next_layer().close(ignored);
        ioc.restart();
        ioc.run_for(std::chrono::milliseconds(500));
    }
};

} // namespace

RemoteJobStream::RemoteJobStream(std::int64_t jobId, std::vector<std::string> variables, double rate,
                                 StreamSink sink, RemoteJobStreamDependencies dependencies, NodeSecret secret,
                                 RemoteJobStreamTiming timing)
    : mJobId(jobId), mVariables(variables), mRate(rate), mDeps(std::move(dependencies)), mSecret(std::move(secret)),
      mTiming(timing), mSink(jobId, std::move(variables), std::move(sink))
{
    mThread = std::thread([this] { run(); });
}

RemoteJobStream::~RemoteJobStream()
{
    stop();
}

void RemoteJobStream::stop()
{
    {
        std::lock_guard lock(mMutex);
        mStopping = true;
        // Wakes the connection's run_one_until, which then sees the flag.
        if (mIoc) net::post(*mIoc, [] {});
    }
    mWake.notify_all();
    if (mThread.joinable() && mThread.get_id() != std::this_thread::get_id()) mThread.join();
}

bool RemoteJobStream::pause(std::chrono::milliseconds period)
{
    std::unique_lock lock(mMutex);
    return !mWake.wait_for(lock, period, [this] { return stopping(); });
}

void RemoteJobStream::run()
{
    auto backoff = kFirstBackoff;
    auto failed = [&] {
        const bool go = pause(backoff);
        backoff = std::min(backoff * 2, mTiming.maxBackoff);
        return go;
    };
    while (!stopping() && !mSink.finished()) {
        std::optional<JobLocation> where;
        try {
            where = mDeps.locate(mJobId);
        } catch (const std::exception&) {
            if (!failed()) break;
            continue;
        }
        if (!where) {
            mSink.finishFromTable(nullptr, JobState::Cancelled, "the job no longer exists");
            break;
        }
        if (isFinished(where->state)) {
            if (finishFromStore(*where) || !failed()) break;
            continue;
        }
        Outcome outcome = Outcome::Moved;
        if (where->heldHere) {
            outcome = followLocally();
        } else if (where->state == JobState::Running && !where->holderAddress.empty()) {
            outcome = followRemote(where->holderAddress);
        } else {
            // Queued: waiting for a worker to claim it (again).
            if (!pause(mTiming.pollPeriod)) break;
            continue;
        }
        if (outcome == Outcome::Ended) break;
        if (outcome == Outcome::Moved) backoff = kFirstBackoff;
        else if (!failed()) break;
    }
}

bool RemoteJobStream::finishFromStore(const JobLocation& where)
{
    std::optional<ResultTable> table;
    try {
        std::vector<std::string> names = mSink.layoutNames();
        table = mDeps.storedResult(mJobId, names.empty() ? mVariables : names);
    } catch (const std::exception&) {
        return false;
    }
    mSink.finishFromTable(table ? &*table : nullptr, where.state, where.error);
    return true;
}

RemoteJobStream::Outcome RemoteJobStream::checkDone(nlohmann::json done)
{
    std::optional<JobLocation> where;
    try {
        where = mDeps.locate(mJobId);
    } catch (const std::exception&) {
        return Outcome::Failed;
    }
    // The node ended its stream but the job goes on (queued again, or running elsewhere).
    if (where && !isFinished(where->state)) return Outcome::Moved;
    mSink.forwardDone(std::move(done));
    return Outcome::Ended;
}

bool RemoteJobStream::holderStillValid(const std::string& address, bool here,
                                       std::optional<Clock::time_point>& finishedSince)
{
    std::optional<JobLocation> where;
    try {
        where = mDeps.locate(mJobId);
    } catch (const std::exception&) {
        return true;   // the store is unreachable; the stream may still be fine
    }
    if (!where) return false;
    if (isFinished(where->state)) {
        // Its node's last frames and done are on their way; if they do not come, the stored
        // result has the rest.
        if (!finishedSince) finishedSince = Clock::now();
        return Clock::now() - *finishedSince < mTiming.finishGrace;
    }
    finishedSince.reset();
    if (where->state != JobState::Running) return false;
    return here ? where->heldHere : (!where->heldHere && where->holderAddress == address);
}

RemoteJobStream::Outcome RemoteJobStream::followLocally()
{
    if (!mDeps.subscribeLocally || !mDeps.unsubscribeLocally) return Outcome::Failed;
    StreamSink stream = mSink.newStream();
    StreamSink local;
    local.progress = stream.progress;
    local.frame = stream.frame;
    // Runs on the job's thread with the hub's lock held: only hand it to our thread.
    local.done = [this](nlohmann::json event) {
        {
            std::lock_guard lock(mMutex);
            mLocalDone = std::move(event);
        }
        mWake.notify_all();
    };
    {
        std::lock_guard lock(mMutex);
        mLocalDone.reset();
    }
    std::uint64_t subscription = 0;
    try {
        subscription = mDeps.subscribeLocally(mJobId, mVariables, mRate, std::move(local));
    } catch (const std::exception&) {
        return Outcome::Failed;
    }
    std::optional<Clock::time_point> finishedSince;
    for (;;) {
        std::optional<nlohmann::json> done;
        {
            std::unique_lock lock(mMutex);
            mWake.wait_for(lock, mTiming.holderCheck, [this] { return stopping() || mLocalDone.has_value(); });
            done = std::exchange(mLocalDone, std::nullopt);
        }
        if (stopping()) {
            mDeps.unsubscribeLocally(subscription);
            return Outcome::Ended;
        }
        if (done) {
            mDeps.unsubscribeLocally(subscription);
            return checkDone(std::move(*done));
        }
        if (!holderStillValid("", true, finishedSince)) {
            mDeps.unsubscribeLocally(subscription);
            return Outcome::Moved;
        }
    }
}

RemoteJobStream::Outcome RemoteJobStream::followRemote(const std::string& address)
{
    std::string host, port;
    if (!splitAddress(address, host, port)) return Outcome::Failed;
    net::io_context ioc;
    {
        std::lock_guard lock(mMutex);
        if (stopping()) return Outcome::Ended;
        mIoc = &ioc;
    }
    Connection c(ioc);
    auto stopped = [this] { return stopping(); };
    auto leave = [&](Outcome outcome) {
        c.abort();
        std::lock_guard lock(mMutex);
        mIoc = nullptr;
        return outcome;
    };
    auto step = [&](const bool& done) {
        return c.run(done, Clock::now() + mTiming.connectTimeout, stopped);
    };

    // Resolve, connect, upgrade as a node, subscribe with binary frames.
    bool done = false;
    beast::error_code ec;
    tcp::resolver resolver(ioc);
    tcp::resolver::results_type endpoints;
    resolver.async_resolve(host, port, [&](beast::error_code e, tcp::resolver::results_type r) {
        ec = e;
        endpoints = std::move(r);
        done = true;
    });
    if (step(done) != Connection::Wait::Done) {
        resolver.cancel();
        return leave(stopping() ? Outcome::Ended : Outcome::Failed);
    }
    if (ec) return leave(Outcome::Failed);
    done = false;
    net::async_connect(c.ws.next_layer(), endpoints, [&](beast::error_code e, const tcp::endpoint&) {
        ec = e;
        done = true;
    });
    if (step(done) != Connection::Wait::Done || ec) return leave(stopping() ? Outcome::Ended : Outcome::Failed);

    c.ws.read_message_max(kMaxMessageBytes);
    c.ws.set_option(websocket::stream_base::decorator(
        [token = mSecret.bearerToken()](websocket::request_type& request) {
            request.set(beast::http::field::authorization, "Bearer " + token);
        }));
    done = false;
    c.ws.async_handshake(host + ":" + port, "/api/v1/ws", [&](beast::error_code e) {
        ec = e;
        done = true;
    });
    if (step(done) != Connection::Wait::Done || ec) return leave(stopping() ? Outcome::Ended : Outcome::Failed);

    nlohmann::json subscribe = {{"id", 1}, {"type", "log.subscribe"}, {"job_id", mJobId}, {"frames", "binary"}};
    if (!mVariables.empty()) subscribe["variables"] = mVariables;
    if (mRate > 0) subscribe["rate"] = std::min(mRate, kMaxSubscribeRate);
    const std::string request = subscribe.dump();
    c.ws.text(true);
    done = false;
    c.ws.async_write(net::buffer(request), [&](beast::error_code e, std::size_t) {
        ec = e;
        done = true;
    });
    if (step(done) != Connection::Wait::Done || ec) return leave(stopping() ? Outcome::Ended : Outcome::Failed);

    // Relay until done, a broken connection, or the job moves. A quiet stream (a job waiting
    // between time slices, or a worker that died without closing) is checked in the store
    // every holderCheck, its read left pending meanwhile.
    StreamSink stream = mSink.newStream();
    std::optional<Clock::time_point> finishedSince;
    bool relayed = false;
    for (;;) {
        done = false;
        c.buffer.clear();
        c.ws.async_read(c.buffer, [&](beast::error_code e, std::size_t) {
            ec = e;
            done = true;
        });
        for (;;) {
            const auto wait = c.run(done, Clock::now() + mTiming.holderCheck, stopped);
            if (wait == Connection::Wait::Done) break;
            if (wait == Connection::Wait::Stopped) return leave(Outcome::Ended);
            if (!holderStillValid(address, false, finishedSince)) return leave(Outcome::Moved);
        }
        if (ec) return leave(relayed ? Outcome::Moved : Outcome::Failed);
        const auto bytes = c.buffer.cdata();
        const std::string_view message(static_cast<const char*>(bytes.data()), bytes.size());
        if (!c.ws.got_text()) {
            DecodedFrame decoded;
            std::string error;
            if (!decodeBinaryFrame(message, decoded, error) || decoded.frame.jobId != mJobId)
                return leave(Outcome::Failed);
            stream.frame(std::move(decoded.frame));
            relayed = true;
            continue;
        }
        const UntrustedJson parsed = parseUntrustedJson(message);
        if (!parsed.ok() || !parsed.value.is_object()) return leave(Outcome::Failed);
        const nlohmann::json& event = parsed.value;
        const std::string type = event.value("type", "");
        if (type == "error") return leave(Outcome::Failed);   // the subscription was refused
        if (event.value("job_id", std::int64_t{0}) != mJobId) continue;
        if (type == "event.progress") {
            stream.progress(event);
            relayed = true;
        } else if (type == "event.done") {
            leave(Outcome::Ended);
            return checkDone(event);
        } else if (type == "event.resync") {
            // The node dropped frames it could not queue for us: a new stream fills the gap.
            return leave(Outcome::Moved);
        }
    }
}

} // namespace tlmhub::server
