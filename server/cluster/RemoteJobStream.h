#pragma once
// Follows one job for one local subscriber when the job may run on another node (issue 19,
// scale-out): API nodes serve the clients, worker nodes run the jobs, all share one database.
// Where the job runs is looked up (locate); then
//  - running on another node: a WebSocket to that node's /api/v1/ws, authenticated as a node
//    (NodeSecret), log.subscribe with binary frames, whose progress, frames and done are
//    relayed to the subscriber's sink;
//  - running here: the local hub (subscribeLocally), through the same sink wrapper;
//  - queued (not claimed yet, or put back after its worker died): looked up again every
//    pollPeriod;
//  - finished: the rest of the stored result, then event.done as StreamHub sends it.
// A broken connection, a node that gives the job up, or a job run again elsewhere only starts
// a new stream: ContinuingSink drops the samples the subscriber already has (a rerun logs the
// same samples), so the frames, concatenated, still equal the stored result, and done comes
// once. A done from a node is checked against the store first: a node that gave the job up
// (its lease lost) may end its subscriptions while the job goes on elsewhere.
//
// Runs on a thread of its own; frames are forwarded as they come, never accumulated. The
// subscriber's sink is called on that thread, or on the local job's thread while the job runs
// here (as StreamHub calls it), never after stop() has returned. Every
// network wait has a timeout, and stop() returns within about one poll of the stop flag
// (milliseconds) unless a locate or storedResult call is in progress (they are not
// interrupted).
#include "core/ResultTable.h"
#include "server/cluster/ContinuingSink.h"
#include "server/cluster/NodeSecret.h"
#include "server/jobs/Job.h"
#include "server/jobs/StreamHub.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace boost::asio {
class io_context;
}

namespace tlmhub::server {

// Where a job is, as the store says (JobStore::info and JobLeaseStore::holder).
struct JobLocation {
    JobState state = JobState::Queued;
    std::string error;           // the job's error once it has finished (as event.done's)
    std::string holderAddress;   // "http://host:port" of the node running it; "" = not running anywhere
    bool heldHere = false;       // this node runs it: follow it through the local hub
};

// What the stream needs from the node it runs in; std::functions so that tests can fake them.
// Each may be called on the stream's thread; exceptions thrown count as a passing failure
// (retried after a backoff).
struct RemoteJobStreamDependencies {
    // nullopt: there is no such job (deleted).
    std::function<std::optional<JobLocation>(std::int64_t jobId)> locate;
    // The job's stored result with `variables` (empty: all columns); nullopt when it has none.
    std::function<std::optional<ResultTable>(std::int64_t jobId, const std::vector<std::string>& variables)>
        storedResult;
    // StreamHub::subscribe on this node; after unsubscribeLocally returns, the sink is not
    // called again.
    std::function<std::uint64_t(std::int64_t jobId, std::vector<std::string> variables, double rate,
                                StreamSink sink)>
        subscribeLocally;
    std::function<void(std::uint64_t subscription)> unsubscribeLocally;
};

struct RemoteJobStreamTiming {
    std::chrono::milliseconds pollPeriod{100};       // a queued job: locate again this often
    std::chrono::milliseconds holderCheck{1000};     // a quiet stream: check its holder this often
    std::chrono::milliseconds connectTimeout{2000};  // resolve, connect, upgrade, subscribe
    std::chrono::milliseconds finishGrace{2000};     // finished in the store, its node's done not yet here
    std::chrono::milliseconds maxBackoff{1000};      // between failed attempts (from 50 ms, doubling)
};

class RemoteJobStream {
public:
    // Starts following at once. `variables` and `rate` as StreamHub::subscribe takes them.
    RemoteJobStream(std::int64_t jobId, std::vector<std::string> variables, double rate, StreamSink sink,
                    RemoteJobStreamDependencies dependencies, NodeSecret secret,
                    RemoteJobStreamTiming timing = {});
    ~RemoteJobStream();   // stop()
    RemoteJobStream(const RemoteJobStream&) = delete;
    RemoteJobStream& operator=(const RemoteJobStream&) = delete;

    // Ends the stream (no done is sent if none was); returns once the thread has ended.
    void stop();
    // event.done has been delivered (the thread ends by itself then).
    bool finished() const { return mSink.finished(); }
    std::int64_t jobId() const { return mJobId; }

private:
    // How following one holder ended.
    enum class Outcome {
        Ended,     // done delivered, or stopped
        Moved,     // the job is elsewhere now (or finished): locate again at once
        Failed,    // could not connect or the connection broke: locate again after a backoff
    };

    void run();
    Outcome followRemote(const std::string& address);
    Outcome followLocally();
    // The rest from the stored result, then done; false when the store could not be read.
    bool finishFromStore(const JobLocation& where);
    // What a done from a node means: forwarded if the store agrees the job has finished.
    Outcome checkDone(nlohmann::json done);
    // Whether following `address` (or here) should go on, after a quiet holderCheck period.
    // `finishedSince` remembers when the store first said finished.
    bool holderStillValid(const std::string& address, bool here,
                          std::optional<std::chrono::steady_clock::time_point>& finishedSince);
    // Sleeps up to `period`; false if stopped meanwhile.
    bool pause(std::chrono::milliseconds period);
    bool stopping() const { return mStopping.load(); }

    const std::int64_t mJobId;
    const std::vector<std::string> mVariables;
    const double mRate;
    const RemoteJobStreamDependencies mDeps;
    const NodeSecret mSecret;
    const RemoteJobStreamTiming mTiming;
    ContinuingSink mSink;

    std::atomic<bool> mStopping{false};
    std::mutex mMutex;
    std::condition_variable mWake;
    boost::asio::io_context* mIoc = nullptr;   // the connection's, while one is open (to wake it)
    std::optional<nlohmann::json> mLocalDone;  // the local hub's done, for the thread to check
    std::thread mThread;
};

} // namespace tlmhub::server
