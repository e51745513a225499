#pragma once
// One subscriber's stream of a job that may start over: the relay of a job running on
// another node reconnects after a broken connection, and a job whose worker died is run again
// from its first sample elsewhere (deterministically: the same samples). Each new stream is
// a fresh StreamSink from newStream(); this class remembers how many time samples and samples
// of each variable it has delivered and drops that many leading samples from the new
// stream's frames, so the subscriber sees every sample once, in order, as from one stream.
// Frames keep the first layout delivered (columns are matched by name), so the subscriber's
// queue can merge them. Calls from a stream older than the newest are ignored (a local hub
// subscription that ends late).
//
// Thread-safe: the streams' sinks may run on a job's thread (the local hub) or the relay's.
#include "core/ResultTable.h"
#include "server/jobs/Job.h"
#include "server/jobs/StreamHub.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace tlmhub::server {

class ContinuingSink {
public:
    // `wanted`: the subscriber's variables (as StreamHub::subscribe takes them).
    ContinuingSink(std::int64_t jobId, std::vector<std::string> wanted, StreamSink out);

    // The sink of a stream that starts from the job's first sample; earlier streams' sinks
    // go quiet. Its done is forwarded (at most one done is ever forwarded).
    StreamSink newStream();
    // Sends what `table` (the job's stored result) holds beyond what was delivered, in the
    // layout delivered so far (else resolved as StreamHub does), then event.done as StreamHub
    // sends it. Nothing if done was already forwarded.
    void finishFromTable(const ResultTable* table, JobState state, const std::string& error);
    // Forwards a done event (e.g. a remote node's) unless one was already forwarded.
    void forwardDone(nlohmann::json event);

    bool finished() const;
    // The variables delivered, when a frame has been (empty otherwise).
    std::vector<std::string> layoutNames() const;
    std::size_t timeDelivered() const;

private:
    void frame(std::uint64_t stream, StreamFrame frame);
    // The samples of `frame` past the current stream's position that the subscriber has not
    // had; advances both positions. Null when there are none.
    std::shared_ptr<FrameSamples> unseen(const StreamFrame& frame);

    const std::int64_t mJobId;
    const std::vector<std::string> mWanted;
    const StreamSink mOut;
    mutable std::mutex mMutex;
    std::uint64_t mStream = 0;   // the newest stream's number
    bool mFinished = false;
    std::shared_ptr<const FrameLayout> mLayout;   // the subscriber's, from its first frame
    std::size_t mTimeDelivered = 0;
    std::vector<std::size_t> mDelivered;   // per mLayout variable
    // Where the current stream is: samples it has sent, per mLayout variable.
    std::size_t mStreamTime = 0;
    std::vector<std::size_t> mStreamAt;
};

} // namespace tlmhub::server
