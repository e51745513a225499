#pragma once
// A subscription's event.frame waiting in its WebSocket's queue, still as numbers: the queue
// merges a slow client's frames into it (samples appended, `dropped` counting the frames
// merged) or gives its stream up for event.resync past the byte limit. `seq` is given when
// the frame is written, so it counts the frames actually sent and has no gaps.
#include "server/http/MergeableFrame.h"
#include "server/jobs/StreamFrame.h"

#include <atomic>
#include <memory>

namespace tlmhub::server {

// What the frames of one subscription share on their connection.
struct FrameStream {
    std::uint64_t id = 0;              // unique on the connection
    FrameEncoding encoding = FrameEncoding::Json;
    std::uint64_t nextSeq = 0;         // only on the connection's strand
    std::atomic<bool> givenUp{false};  // set on the strand; the job's thread reads it to stop early
};

class QueuedFrame final : public MergeableFrame {
public:
    QueuedFrame(StreamFrame frame, std::shared_ptr<FrameStream> stream)
        : mFrame(std::move(frame)), mStream(std::move(stream)) {}

    std::uint64_t stream() const override { return mStream->id; }
    void merge(MergeableFrame& later) override;
    std::size_t bytes() const override { return mFrame.encodedBytesBound(mStream->encoding); }
    OutgoingMessage message() override;
    std::string giveUp() override;
    bool streamGivenUp() const override { return mStream->givenUp.load(); }

private:
    StreamFrame mFrame;
    std::shared_ptr<FrameStream> mStream;
};

} // namespace tlmhub::server
