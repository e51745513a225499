#pragma once
// Process-wide gauges of the transport, read by the administrators' stats route and by
// tests that check memory stays bounded (what is queued, not what the allocator keeps).
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace tlmhub::server {

struct TransportStats {
    std::atomic<std::int64_t> webSockets{0};          // open WebSocket sessions
    std::atomic<std::int64_t> webSocketQueuedBytes{0};   // messages waiting to be written, all sockets
    std::atomic<std::uint64_t> webSocketsClosedForBacklog{0};

    static TransportStats& instance();
};

} // namespace tlmhub::server
