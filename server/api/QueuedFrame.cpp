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
    // A live session cannot be read back later: it ends (its sink sees givenUp).
    if (const auto live = mFrame.live) {
        mFrame = {};
        nlohmann::json speed = live->speed ? nlohmann::json(*live->speed) : nlohmann::json("max");
        return toJsonText({{"type", "event.live.state"}, {"session_id", live->sessionId}, {"state", "stopped"},
                           {"speed", std::move(speed)}, {"achieved_speed", 0.0}, {"model_time", live->modelTime},
                           {"reason", "failed"}, {"message", "the connection is too slow for the session's frames"}});
    }
    const std::int64_t jobId = mFrame.jobId;
    mFrame = {};   // the samples go now
    return toJsonText({{"type", "event.resync"}, {"job_id", jobId}});
}

} // namespace tlmhub::server
