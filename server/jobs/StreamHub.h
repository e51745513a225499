#pragma once
// Live events of running jobs for whoever subscribed (WebSocket sessions): event.progress,
// event.frame (new logged samples since the subscriber's previous frame, at most `rate` per
// second) and event.done. The job's thread publishes; sinks run on that thread, with the
// hub's lock held, so a sink must not block and must not call back into the hub (the WS
// layer only queues the event onto its session).
//
// Frames of one subscription, concatenated, equal the job's stored result: each
// subscription remembers how many samples of each of its variables it has sent, and the final
// frames (from the stored ResultTable) send the rest before event.done. Frames go out as
// numbers (StreamFrame), numbered by whoever writes them, so that a slow connection can merge
// them without losing samples or leaving gaps in `seq`. Subscriptions of a job that stream the
// same variables and have sent as much share each publication's samples (and so its encoding).
#include "server/jobs/FrameSource.h"
#include "server/jobs/Job.h"
#include "server/jobs/StreamFrame.h"
#include "server/protocol/ProtocolConstants.generated.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace tlmhub::server {

// Where a subscription's events go; all run on the publishing thread (see above).
struct StreamSink {
    // event.progress: a level, so a newer one may replace one not yet sent.
    std::function<void(nlohmann::json event)> progress;
    std::function<void(StreamFrame frame)> frame;      // the samples of event.frame
    std::function<void(nlohmann::json event)> done;    // event.done
    // The job stopped here without an end of its own: this node lost its lease and another
    // node runs the job again (JobLeaseStore.h). Optional; the subscription has ended.
    std::function<void()> lost;
};

class StreamHub {
public:
    static constexpr std::size_t kMaxFrameVariables = protocol::kMaxStreamVariables;
    static constexpr double kDefaultRate = protocol::kDefaultFrameRate;   // frames per second
    static constexpr double kMaxRate = protocol::kMaxFrameRate;

    // `variables`: ResultTable column names (unknown ones are ignored, at most
    // kMaxFrameVariables kept); empty = the first kMaxFrameVariables logged variables. `rate`
    // <= 0 means the default.
    std::uint64_t subscribe(std::int64_t jobId, std::vector<std::string> variables, double rate,
                            StreamSink sink);
    void unsubscribe(std::uint64_t subscription);
    bool hasSubscribers(std::int64_t jobId) const;
    std::size_t subscriptionCount() const;

    // --- for the job's thread ---
    void publishProgress(std::int64_t jobId, double progress);
    // A frame for every subscription of the job whose interval has passed and that has new
    // samples.
    void publishFrames(std::int64_t jobId, const FrameSource& source);
    // The remaining samples (if `source`), then event.done; the job's subscriptions end.
    void finish(std::int64_t jobId, const FrameSource* source, JobState state, const std::string& error);
    // The job's subscriptions end without event.done (StreamSink::lost): its end is not this
    // node's to tell any more.
    void abandon(std::int64_t jobId);
    // Same as finish for one subscription (a subscriber arriving after the job finished); nothing if
    // the subscription has already ended.
    void finishSubscription(std::uint64_t subscription, const FrameSource* source, JobState state,
                            const std::string& error);

private:
    struct Subscription {
        std::int64_t jobId = 0;
        std::vector<std::string> wanted;
        std::chrono::steady_clock::duration interval{};
        StreamSink sink;
        std::chrono::steady_clock::time_point lastFrame{};
        // The variables it streams, resolved at its first frame; shared with its frames and
        // with the job's other subscriptions of the same variables.
        std::shared_ptr<const FrameLayout> layout;
        std::vector<std::size_t> sent;    // samples sent per variable
        std::size_t timeSent = 0;
    };
    // What one publication made, for the next subscription that is where this one was.
    struct Published {
        const FrameLayout* layout = nullptr;
        std::vector<std::size_t> sentBefore;
        std::size_t timeSentBefore = 0;
        std::shared_ptr<const FrameSamples> samples;   // null when there was nothing new
        std::vector<std::size_t> sentAfter;
        std::size_t timeSentAfter = 0;
    };
    using Publication = std::vector<Published>;

    void resolveLayout(Subscription& s, const FrameSource& source);
    void sendFrame(Subscription& s, const FrameSource& source, Publication& publication);
    static void sendDone(Subscription& s, JobState state, const std::string& error);

    mutable std::mutex mMutex;
    std::uint64_t mNextId = 1;
    std::map<std::uint64_t, Subscription> mSubscriptions;
    std::multimap<std::int64_t, std::uint64_t> mByJob;
};

} // namespace tlmhub::server
