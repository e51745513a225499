#include "server/api/QueuedFrame.h"

#include "server/http/JsonText.h"

namespace tlmhub::server {

void QueuedFrame::merge(MergeableFrame& later)
{
    // Same stream, so the same type: a connection's streams are all QueuedFrames.
    mFrame.append(std::move(static_cast<QueuedFrame&>(later).mFrame));
}

OutgoingMessage QueuedFrame::message()
{
    const std::uint64_t seq = mStream->nextSeq++;
    if (mStream->encoding == FrameEncoding::Binary) return {mFrame.binaryMessage(seq), true};
    return {mFrame.jsonText(seq)};
}

std::string QueuedFrame::giveUp()
{
    mStream->givenUp = true;
    const std::int64_t jobId = mFrame.jobId;
    mFrame = {};   // the samples go now
    return toJsonText({{"type", "event.resync"}, {"job_id", jobId}});
}

} // namespace tlmhub::server
