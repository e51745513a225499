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
        mSubscriptions.at(j->second).sink.event({{"type", "event.progress"}, {"job_id", jobId}, {"progress", progress}});
}

void StreamHub::publishFrames(std::int64_t jobId, const FrameSource& source)
{
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard lock(mMutex);
    auto [first, last] = mByJob.equal_range(jobId);
    for (auto j = first; j != last; ++j) {
        Subscription& s = mSubscriptions.at(j->second);
        if (now - s.lastFrame < s.interval) continue;
        sendFrame(s, source);
    }
}

void StreamHub::finish(std::int64_t jobId, const FrameSource* source, JobState state, const std::string& error)
{
    std::lock_guard lock(mMutex);
    auto [first, last] = mByJob.equal_range(jobId);
    for (auto j = first; j != last; ++j) {
        Subscription& s = mSubscriptions.at(j->second);
        if (source) sendFrame(s, *source);
        sendDone(s, state, error);
        mSubscriptions.erase(j->second);
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
    if (source) sendFrame(s, *source);
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

// New samples since the subscription's previous frame; nothing when there are none.
void StreamHub::sendFrame(Subscription& s, const FrameSource& source)
{
    if (!s.names) {
        std::vector<std::string> names;
        if (s.wanted.empty()) {
            const auto& all = source.names();
            names.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(
                                                        std::min(all.size(), kMaxFrameVariables)));
        } else {
            for (const auto& name : s.wanted) {
                if (names.size() == kMaxFrameVariables) break;
                if (source.find(name) && std::find(names.begin(), names.end(), name) == names.end())
                    names.push_back(name);
            }
        }
        s.sent.assign(names.size(), 0);
        s.names = std::make_shared<const std::vector<std::string>>(std::move(names));
    }
    const std::size_t timeTo = source.timeCount();
    bool anything = timeTo > s.timeSent;
    StreamFrame frame;
    frame.jobId = s.jobId;
    frame.names = s.names;
    source.appendTime(s.timeSent, timeTo, frame.time);
    frame.columns.resize(s.names->size());
    for (std::size_t i = 0; i < s.names->size(); ++i) {
        std::size_t to = s.sent[i];
        if (auto column = source.find((*s.names)[i])) {
            to = std::max(to, source.count(*column));
            source.appendData(*column, s.sent[i], to, frame.columns[i]);
        }
        anything = anything || !frame.columns[i].empty();
        s.sent[i] = to;
    }
    if (!anything) return;
    s.timeSent = std::max(s.timeSent, timeTo);
    s.lastFrame = std::chrono::steady_clock::now();
    s.sink.frame(std::move(frame));
}

void StreamHub::sendDone(Subscription& s, JobState state, const std::string& error)
{
    nlohmann::json done = {{"type", "event.done"}, {"job_id", s.jobId}, {"state", jobStateName(state)}};
    if (!error.empty()) done["error"] = error;
    s.sink.event(std::move(done));
}

} // namespace tlmhub::server
