#pragma once
// Who follows which study: WebSocket connections that sent study.subscribe get its
// event.study.progress messages. A study's worker publishes; sinks run on that thread with
// the hub's lock held, so a sink must only queue the event (as the WebSocket layer does).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>

namespace tlmhub::server {

class StudyProgressHub {
public:
    using Sink = std::function<void(const nlohmann::json& event)>;

    // A study that finished lately gets its last event at once (on this thread) and no
    // subscription (0): a subscriber that came just after the end still sees it.
    std::uint64_t subscribe(std::int64_t studyId, Sink sink);
    void unsubscribe(std::uint64_t subscription);
    // Which run of the study its events belong to: 0 until it is resumed, then one more at
    // each reopen. An execution takes it when made and publishes with it.
    std::uint64_t generation(std::int64_t studyId) const;
    // To every subscriber of the study; dropped when `generation` is not the study's current
    // one (a late event of the run before a resume).
    void publish(std::int64_t studyId, std::uint64_t generation, const nlohmann::json& event);
    // The study's last event: published, then its subscriptions end; dropped as publish does.
    void finish(std::int64_t studyId, std::uint64_t generation, const nlohmann::json& event);
    // The study runs again (resumed): its last event is forgotten, so a subscriber follows its
    // new progress instead of being told it ended, and its generation advances, so the run
    // that ended cannot end the new one by finishing late (it stores its end before it
    // publishes it, and a client may resume in between).
    void reopen(std::int64_t studyId);
    std::size_t subscriptionCount() const;

private:
    struct Subscription {
        std::int64_t studyId;
        Sink sink;
    };
    mutable std::mutex mMutex;
    std::uint64_t mNextId = 1;
    std::map<std::uint64_t, Subscription> mSubscriptions;
    // The last events of the latest finished studies, oldest first out.
    static constexpr std::size_t kFinishedKept = 256;
    std::map<std::int64_t, nlohmann::json> mFinished;
    std::deque<std::int64_t> mFinishedOrder;
    std::map<std::int64_t, std::uint64_t> mGenerations;   // resumed studies only
    std::uint64_t current(std::int64_t studyId) const;    // caller holds mMutex
};

} // namespace tlmhub::server
