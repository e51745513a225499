#pragma once
// Where a client's log.subscribe goes. One node: the job queue's local hub. A deployment of
// several nodes (a node secret is configured): a RemoteJobStream per subscription, which
// follows the job to whichever node runs it (here or elsewhere, again elsewhere after a
// worker died) or to its stored result. Another node's subscription (the node principal)
// always stays on the local hub, so relays never chain from node to node.
#include "server/cluster/NodeSecret.h"
#include "server/cluster/RemoteJobStream.h"
#include "server/jobs/JobQueue.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

namespace tlmhub::server {

class JobStreams {
public:
    // `secret`: nullopt on a single node (no relays).
    JobStreams(JobQueue& queue, std::optional<NodeSecret> secret);
    ~JobStreams();   // stops every relay

    // As JobQueue::subscribe; `fromNode`: the subscriber is another node.
    std::uint64_t subscribe(std::int64_t jobId, std::vector<std::string> variables, double rate, StreamSink sink,
                            bool fromNode);
    void unsubscribe(std::uint64_t subscription);
    std::size_t relayCount();

private:
    // Relay ids sit above the hub's, which count up from 1.
    static constexpr std::uint64_t kRelayIds = std::uint64_t(1) << 62;
    // Relays whose job has ended are dropped when the next one starts.
    void dropFinished();   // caller holds mMutex

    JobQueue& mQueue;
    std::optional<NodeSecret> mSecret;
    std::mutex mMutex;
    std::uint64_t mNextId = kRelayIds;
    std::map<std::uint64_t, std::unique_ptr<RemoteJobStream>> mRelays;
};

} // namespace tlmhub::server
