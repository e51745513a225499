#include "server/jobs/StreamHub.h"

#include <algorithm>

namespace tlmhub::server {

std::uint64_t StreamHub::subscribe(std::int64_t jobId, std::vector<std::string> variables, double rate,
                                   StreamSink sink)
{
    if (!(rate > 0.0)) rate = kDefaultRate;
    rate = std::min(rate, kMaxRate);
    Subscription s;
    s.jobId = jobId;
    s.wanted = std::move(variables);
    s.interval = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(1.0 / rate));
    s.sink = std::move(sink);
    std::lock_guard lock(mMutex);
    const std::uint64_t id = mNextId++;
    mSubscriptions.emplace(id, std::move(s));
    mByJob.emplace(jobId, id);
    return id;
}

void StreamHub::unsubscribe(std::uint64_t subscription)
{
    std::lock_guard lock(mMutex);
    auto it = mSubscriptions.find(subscription);
    if (it == mSubscriptions.end()) return;
    auto [first, last] = mByJob.equal_range(it->second.jobId);
    for (auto j = first; j != last; ++j) {
        if (j->second == subscription) {
            mByJob.erase(j);
            break;
        }
    }
    mSubscriptions.erase(it);
}

bool StreamHub::hasSubscribers(std::int64_t jobId) const
{
    std::lock_guard lock(mMutex);
    return mByJob.count(jobId) != 0;
}

std::size_t StreamHub::subscriptionCount() const
{
    std::lock_guard lock(mMutex);
    return mSubscriptions.size();
}

void StreamHub::publishProgress(std::int64_t jobId, double progress)
{
    std::lock_guard lock(mMutex);
    auto [first, last] = mByJob.equal_range(jobId);
    for (auto j = first; j != last; ++j)
        mSubscriptions.at(j->second).sink.progress({{"type", "event.progress"}, {"job_id", jobId}, {"progress", progress}});
}

void StreamHub::publishFrames(std::int64_t jobId, const FrameSource& source)
{
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard lock(mMutex);
    Publication publication;
    auto [first, last] = mByJob.equal_range(jobId);
    for (auto j = first; j != last; ++j) {
        Subscription& s = mSubscriptions.at(j->second);
        if (now - s.lastFrame < s.interval) continue;
        sendFrame(s, source, publication);
    }
}

void StreamHub::finish(std::int64_t jobId, const FrameSource* source, JobState state, const std::string& error)
{
    std::lock_guard lock(mMutex);
    Publication publication;
    auto [first, last] = mByJob.equal_range(jobId);
    for (auto j = first; j != last; ++j) {
        Subscription& s = mSubscriptions.at(j->second);
        if (source) sendFrame(s, *source, publication);
        sendDone(s, state, error);
    }
    for (auto j = first; j != last; ++j) mSubscriptions.erase(j->second);
    mByJob.erase(first, last);
}

void StreamHub::abandon(std::int64_t jobId)
{
    std::lock_guard lock(mMutex);
    auto [first, last] = mByJob.equal_range(jobId);
    for (auto j = first; j != last; ++j) {
        auto it = mSubscriptions.find(j->second);
        if (it->second.sink.lost) it->second.sink.lost();
        mSubscriptions.erase(it);
    }
    mByJob.erase(first, last);
}

void StreamHub::finishSubscription(std::uint64_t subscription, const FrameSource* source, JobState state,
                                   const std::string& error)
{
    std::lock_guard lock(mMutex);
    auto it = mSubscriptions.find(subscription);
    if (it == mSubscriptions.end()) return;
    Subscription& s = it->second;
    Publication publication;
    if (source) sendFrame(s, *source, publication);
    sendDone(s, state, error);
    auto [first, last] = mByJob.equal_range(s.jobId);
    for (auto j = first; j != last; ++j) {
        if (j->second == subscription) {
            mByJob.erase(j);
            break;
        }
    }
    mSubscriptions.erase(it);
}

// The variables a subscription streams; a layout another subscription of the job already
// has is shared, so that their frames can share samples.
void StreamHub::resolveLayout(Subscription& s, const FrameSource& source)
{
    std::vector<std::string> names;
    if (s.wanted.empty()) {
        const auto& all = source.names();
        names.assign(all.begin(),
                     all.begin() + static_cast<std::ptrdiff_t>(std::min(all.size(), kMaxFrameVariables)));
    } else {
        for (const auto& name : s.wanted) {
            if (names.size() == kMaxFrameVariables) break;
            if (source.find(name) && std::find(names.begin(), names.end(), name) == names.end())
                names.push_back(name);
        }
    }
    s.sent.assign(names.size(), 0);
    auto [first, last] = mByJob.equal_range(s.jobId);
    for (auto j = first; j != last; ++j) {
        const Subscription& other = mSubscriptions.at(j->second);
        if (other.layout && other.layout->names == names) {
            s.layout = other.layout;
            return;
        }
    }
    s.layout = std::make_shared<const FrameLayout>(std::move(names));
}

// New samples since the subscription's previous frame; nothing when there are none. A
// subscription that is where an earlier one of this publication was gets the same samples.
void StreamHub::sendFrame(Subscription& s, const FrameSource& source, Publication& publication)
{
    if (!s.layout) resolveLayout(s, source);
    const Published* same = nullptr;
    for (const Published& p : publication)
        if (p.layout == s.layout.get() && p.sentBefore == s.sent && p.timeSentBefore == s.timeSent) same = &p;
    if (!same) {
        Published p;
        p.layout = s.layout.get();
        p.sentBefore = s.sent;
        p.timeSentBefore = s.timeSent;
        auto samples = std::make_shared<FrameSamples>();
        const std::size_t timeTo = source.timeCount();
        source.appendTime(s.timeSent, timeTo, samples->time);
        const auto& names = s.layout->names;
        samples->columns.resize(names.size());
        p.sentAfter = s.sent;
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (auto column = source.find(names[i])) {
                p.sentAfter[i] = std::max(s.sent[i], source.count(*column));
                source.appendData(*column, s.sent[i], p.sentAfter[i], samples->columns[i]);
            }
        }
        p.timeSentAfter = std::max(s.timeSent, timeTo);
        if (!samples->empty()) p.samples = std::move(samples);
        publication.push_back(std::move(p));
        same = &publication.back();
    }
    if (!same->samples) return;
    s.sent = same->sentAfter;
    s.timeSent = same->timeSentAfter;
    s.lastFrame = std::chrono::steady_clock::now();
    StreamFrame frame;
    frame.jobId = s.jobId;
    frame.layout = s.layout;
    frame.parts.push_back(same->samples);
    s.sink.frame(std::move(frame));
}

void StreamHub::sendDone(Subscription& s, JobState state, const std::string& error)
{
    nlohmann::json done = {{"type", "event.done"}, {"job_id", s.jobId}, {"state", jobStateName(state)}};
    if (!error.empty()) done[endedByModel(state, error) ? "stop_reason" : "error"] = error;
    s.sink.done(std::move(done));
}

} // namespace tlmhub::server
