// Fuzzes decodeBinaryFrame, which reads binary event.frame messages from another node (the
// relay of server/cluster/RemoteJobStream). What it accepts must encode again
// (StreamFrame::binaryMessage) into a message that decodes to the same samples, bit for bit.
#include "server/jobs/StreamFrameDecoding.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace {

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace tlmhub::server;
    DecodedFrame first;
    std::string error;
    if (!decodeBinaryFrame(std::string_view(reinterpret_cast<const char*>(data), size), first, error)) {
        if (error.empty()) std::abort();   // a refusal always says why
        return 0;
    }
    first.frame.merged = first.dropped;
    DecodedFrame second;
    if (!decodeBinaryFrame(first.frame.binaryMessage(first.seq), second, error)) std::abort();
    const FrameSamples& a = *first.frame.parts.at(0);
    const FrameSamples& b = *second.frame.parts.at(0);
    if (second.seq != first.seq || second.dropped != first.dropped || second.frame.jobId != first.frame.jobId ||
        second.frame.layout->names != first.frame.layout->names || !sameBits(a.time, b.time) ||
        a.columns.size() != b.columns.size())
        std::abort();
    for (std::size_t i = 0; i < a.columns.size(); ++i)
        if (!sameBits(a.columns[i], b.columns[i])) std::abort();
    return 0;
}
