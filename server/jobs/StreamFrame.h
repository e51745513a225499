#pragma once
// The samples of one event.frame as numbers: a time vector and one column per streamed
// variable. A frame stays data until it is written, so frames a slow connection cannot send
// yet are merged (their parts appended) instead of dropped. A column may be a little shorter
// than the time vector in one frame (its log lags by a sample); concatenated, they all match
// the stored result.
//
// What a job publishes for one variable set is encoded once: every subscription that streams
// the same variables from the same sample on shares one FrameSamples, whose JSON text the first
// connection to write it makes for all of them. A frame is sent as JSON text (numbers in their
// shortest form that reads back exactly, std::to_chars) or, if the client asked, as a binary
// message: a little-endian uint32 header length, the header (BinaryFrameHeader, JSON), zero
// bytes up to an offset that is a multiple of 8, then float64 little-endian samples: the time
// vector, then each variable's column in the header's order.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

// The variables a subscription streams, resolved at its first frame.
struct FrameLayout {
    explicit FrameLayout(std::vector<std::string> variableNames);
    std::vector<std::string> names;
    std::vector<std::string> quotedNames;   // as JSON strings, quotes and escapes included
};

// One publication's samples; immutable once published, shared by the frames that carry it.
class FrameSamples {
public:
    std::vector<double> time;
    std::vector<std::vector<double>> columns;   // columns[i]: samples of layout.names[i]

    bool empty() const;
    std::size_t valueCount() const;
    // `"time":[...],"variables":{...}`, made on the first call and kept.
    const std::string& jsonBody(const FrameLayout& layout) const;

private:
    mutable std::once_flag mEncoded;
    mutable std::string mJsonBody;
};

enum class FrameEncoding { Json, Binary };

// A live session's frame (event.live.frame) names its session and when it was taken instead
// of a job; a merged frame keeps the latest stamp.
struct LiveFrameStamp {
    std::uint64_t sessionId = 0;
    double modelTime = 0.0;   // s
    double wallTime = 0.0;    // s since the session started
    std::optional<double> speed;   // the session's pace; none: "max"
};

struct StreamFrame {
    std::int64_t jobId = 0;
    std::optional<LiveFrameStamp> live;
    std::shared_ptr<const FrameLayout> layout;
    std::vector<std::shared_ptr<const FrameSamples>> parts;   // in order; more than one once merged
    std::uint64_t merged = 0;                                 // frames merged into this one

    // Appends the next frame of the same subscription.
    void append(StreamFrame&& later);
    // At least the size of the encoded message.
    std::size_t encodedBytesBound(FrameEncoding encoding) const;
    // event.frame (event.live.frame with `live`); `dropped` is the number of frames merged
    // into this one.
    std::string jsonText(std::uint64_t seq) const;
    std::string binaryMessage(std::uint64_t seq) const;
};

} // namespace tlmhub::server
