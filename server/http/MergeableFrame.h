#pragma once
// A stream message that a WebSocket's queue holds as data rather than text until its turn to
// be written comes. While the client is slow, a later frame of the same stream is merged into
// it (nothing is lost); when a stream's waiting data would pass the socket's byte limit, the
// stream gives way to a short notice. The transport knows nothing of what the data is: the
// application's frame type (server/api/QueuedFrame) merges and writes it.
#include "server/http/OutgoingMessage.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace tlmhub::server {

class MergeableFrame {
public:
    virtual ~MergeableFrame() = default;
    // Frames merge only with frames of the same stream; ids are unique per connection.
    virtual std::uint64_t stream() const = 0;
    // Appends `later`, the next frame of the same stream, to this one.
    virtual void merge(MergeableFrame& later) = 0;
    // At least the size of message(): what the frame counts against the byte limit.
    virtual std::size_t bytes() const = 0;
    // The message to write; called once, when the frame's turn comes.
    virtual OutgoingMessage message() = 0;
    // The stream gives up: this frame's data goes and the returned notice is sent in its
    // place; from then on streamGivenUp() is true for every frame of the stream.
    virtual std::string giveUp() = 0;
    virtual bool streamGivenUp() const = 0;
};

} // namespace tlmhub::server
