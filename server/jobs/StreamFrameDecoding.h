#pragma once
// The inverse of StreamFrame::binaryMessage: a binary event.frame back into numbers, for a
// node that relays another node's stream (server/cluster/RemoteJobStream.h). The message
// comes from the network, so every length, header field and count is checked before it is
// used, and a malformed message is an error, never a crash or an allocation larger than the
// message itself.
#include "server/jobs/StreamFrame.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace tlmhub::server {

struct DecodedFrame {
    std::uint64_t seq = 0;
    std::uint64_t dropped = 0;   // frames the sender merged into this one
    // jobId, a layout of the header's variable names and one FrameSamples part (merged is 0).
    StreamFrame frame;
};

// False with `error` (in words) when `message` is not a well-formed binary event.frame:
// header length past the end, header not the BinaryFrameHeader object (unknown or missing
// keys, wrong types, negative counts, duplicate names), non-zero padding, or a sample count
// that does not match the bytes that follow.
bool decodeBinaryFrame(std::string_view message, DecodedFrame& out, std::string& error);

} // namespace tlmhub::server
