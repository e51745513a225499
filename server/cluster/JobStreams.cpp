#include "server/cluster/JobStreams.h"

namespace tlmhub::server {

JobStreams::JobStreams(JobQueue& queue, std::optional<NodeSecret> secret)
    : mQueue(queue), mSecret(std::move(secret))
{
}

JobStreams::~JobStreams()
{
    std::map<std::uint64_t, std::unique_ptr<RemoteJobStream>> relays;
    {
        std::lock_guard lock(mMutex);
        relays.swap(mRelays);
    }
    relays.clear();   // each stops and joins its thread
}

std::uint64_t JobStreams::subscribe(std::int64_t jobId, std::vector<std::string> variables, double rate,
                                    StreamSink sink, bool fromNode)
{
    if (!mSecret || fromNode) return mQueue.subscribe(jobId, std::move(variables), rate, std::move(sink));
    RemoteJobStreamDependencies dependencies;
    dependencies.locate = [this](std::int64_t id) -> std::optional<JobLocation> {
        const auto info = mQueue.store().info(id);
        if (!info) return std::nullopt;
        JobLocation where{info->state, info->error, {}, false};
        if (info->state == JobState::Running) {
            if (const auto holder = mQueue.leases().holder(id)) {
                where.heldHere = holder->nodeId == mQueue.node().id;
                where.holderAddress = holder->address;
            }
        }
        return where;
    };
    dependencies.storedResult = [this](std::int64_t id, const std::vector<std::string>& wanted) {
        return mQueue.results().result(id, wanted);
    };
    dependencies.subscribeLocally = [this](std::int64_t id, std::vector<std::string> wanted, double r,
                                           StreamSink local) {
        return mQueue.subscribe(id, std::move(wanted), r, std::move(local));
    };
    dependencies.unsubscribeLocally = [this](std::uint64_t id) { mQueue.hub().unsubscribe(id); };
    auto relay = std::make_unique<RemoteJobStream>(jobId, std::move(variables), rate, std::move(sink),
                                                   std::move(dependencies), *mSecret);
    std::lock_guard lock(mMutex);
    dropFinished();
    const std::uint64_t id = mNextId++;
    mRelays.emplace(id, std::move(relay));
    return id;
}

void JobStreams::unsubscribe(std::uint64_t subscription)
{
    if (subscription < kRelayIds) return mQueue.hub().unsubscribe(subscription);
    std::unique_ptr<RemoteJobStream> relay;
    {
        std::lock_guard lock(mMutex);
        const auto found = mRelays.find(subscription);
        if (found == mRelays.end()) return;
        relay = std::move(found->second);
        mRelays.erase(found);
    }
    relay.reset();   // stops outside the lock
}

std::size_t JobStreams::relayCount()
{
    std::lock_guard lock(mMutex);
    return mRelays.size();
}

void JobStreams::dropFinished()
{
    // A finished relay's thread has ended by itself: destroying it does not wait.
    std::erase_if(mRelays, [](const auto& entry) { return entry.second->finished(); });
}

} // namespace tlmhub::server
