#include "server/jobs/StreamFrame.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace tlmhub::server {

namespace {

static_assert(std::endian::native == std::endian::little,
              "binary frames copy float64 samples as they lie in memory");

// The longest shortest-round-trip double ("-2.2250738585072014e-308") and its comma.
constexpr std::size_t kNumberBytes = 25;
// Everything but numbers and names: keys, ids, brackets (a live frame's stamp included).
constexpr std::size_t kFrameOverheadBytes = 320;

// Writes into a buffer sized by a bound, then trims it: no per-number reallocation.
class TextWriter {
public:
    explicit TextWriter(std::size_t bound) { mText.resize(bound); }
    void put(std::string_view s)
    {
        std::memcpy(mText.data() + mSize, s.data(), s.size());
        mSize += s.size();
    }
    void put(char c) { mText[mSize++] = c; }
    void putInteger(std::uint64_t v)
    {
        mSize = static_cast<std::size_t>(std::to_chars(mText.data() + mSize, mText.data() + mText.size(), v).ptr -
                                         mText.data());
    }
    // JSON has no NaN or infinity: they go as null, as nlohmann writes them. Negative zero
    // keeps a fraction: parsers that read "-0" as an integer lose its sign.
    void putNumber(double v)
    {
        if (!std::isfinite(v)) return put("null");
        if (v == 0.0 && std::signbit(v)) return put("-0.0");
        mSize = static_cast<std::size_t>(std::to_chars(mText.data() + mSize, mText.data() + mText.size(), v).ptr -
                                         mText.data());
    }
    // The values of every part, in order, as one JSON array.
    template <typename Parts, typename Values>
    void putArray(const Parts& parts, Values values)
    {
        put('[');
        bool first = true;
        for (const auto& part : parts) {
            for (double v : values(*part)) {
                if (!first) put(',');
                first = false;
                putNumber(v);
            }
        }
        put(']');
    }
    std::string take()
    {
        mText.resize(mSize);
        return std::move(mText);
    }

private:
    std::string mText;
    std::size_t mSize = 0;
};

const std::vector<double> kNoSamples;

const std::vector<double>& columnOf(const FrameSamples& samples, std::size_t i)
{
    return i < samples.columns.size() ? samples.columns[i] : kNoSamples;
}

std::size_t namesBytes(const FrameLayout& layout)
{
    std::size_t bytes = 0;
    for (const auto& quoted : layout.quotedNames) bytes += quoted.size() + 32;
    return bytes;
}

std::size_t valueCount(const std::vector<std::shared_ptr<const FrameSamples>>& parts)
{
    std::size_t n = 0;
    for (const auto& part : parts) n += part->valueCount();
    return n;
}

// `parts`: FrameSamples pointers (raw or shared) in order.
template <typename Parts>
void putBody(TextWriter& out, const FrameLayout& layout, const Parts& parts)
{
    out.put("\"time\":");
    out.putArray(parts, [](const FrameSamples& s) -> const std::vector<double>& { return s.time; });
    out.put(",\"variables\":{");
    for (std::size_t i = 0; i < layout.names.size(); ++i) {
        if (i) out.put(',');
        out.put(layout.quotedNames[i]);
        out.put(':');
        out.putArray(parts, [i](const FrameSamples& s) -> const std::vector<double>& { return columnOf(s, i); });
    }
    out.put('}');
}

// `{"type":...,"seq":N,"dropped":N`: a job's frame, or a live session's with its stamp.
void putHead(TextWriter& out, const StreamFrame& frame, std::uint64_t seq)
{
    if (frame.live) {
        out.put("{\"type\":\"event.live.frame\",\"session_id\":");
        out.putInteger(frame.live->sessionId);
        out.put(",\"model_time\":");
        out.putNumber(frame.live->modelTime);
        out.put(",\"wall_time\":");
        out.putNumber(frame.live->wallTime);
    } else {
        out.put("{\"type\":\"event.frame\",\"job_id\":");
        out.putInteger(static_cast<std::uint64_t>(frame.jobId));
    }
    out.put(",\"seq\":");
    out.putInteger(seq);
    out.put(",\"dropped\":");
    out.putInteger(frame.merged);
}

std::size_t bodyBytesBound(const FrameLayout& layout, std::size_t values)
{
    return kFrameOverheadBytes + namesBytes(layout) + values * kNumberBytes;
}

} // namespace

FrameLayout::FrameLayout(std::vector<std::string> variableNames) : names(std::move(variableNames))
{
    for (const auto& name : names) quotedNames.push_back(nlohmann::json(name).dump());
}

bool FrameSamples::empty() const { return valueCount() == 0; }

std::size_t FrameSamples::valueCount() const
{
    std::size_t n = time.size();
    for (const auto& column : columns) n += column.size();
    return n;
}

const std::string& FrameSamples::jsonBody(const FrameLayout& layout) const
{
    std::call_once(mEncoded, [&] {
        const FrameSamples* self[] = {this};
        TextWriter out(bodyBytesBound(layout, valueCount()));
        putBody(out, layout, self);
        mJsonBody = out.take();
    });
    return mJsonBody;
}

void StreamFrame::append(StreamFrame&& later)
{
    parts.insert(parts.end(), std::make_move_iterator(later.parts.begin()),
                 std::make_move_iterator(later.parts.end()));
    merged += later.merged + 1;
    if (later.live) live = later.live;
}

std::size_t StreamFrame::encodedBytesBound(FrameEncoding encoding) const
{
    const std::size_t values = valueCount(parts);
    if (encoding == FrameEncoding::Binary) return kFrameOverheadBytes + namesBytes(*layout) + 8 + values * 8;
    return bodyBytesBound(*layout, values);
}

std::string StreamFrame::jsonText(std::uint64_t seq) const
{
    const std::string* body = parts.size() == 1 ? &parts.front()->jsonBody(*layout) : nullptr;
    TextWriter out(body ? kFrameOverheadBytes + body->size() : encodedBytesBound(FrameEncoding::Json));
    putHead(out, *this, seq);
    out.put(',');
    if (body) out.put(*body);
    else putBody(out, *layout, parts);
    out.put('}');
    return out.take();
}

std::string StreamFrame::binaryMessage(std::uint64_t seq) const
{
    std::size_t timeSamples = 0;
    std::vector<std::size_t> samples(layout->names.size(), 0);
    for (const auto& part : parts) {
        timeSamples += part->time.size();
        for (std::size_t i = 0; i < samples.size(); ++i) samples[i] += columnOf(*part, i).size();
    }
    TextWriter header(kFrameOverheadBytes + namesBytes(*layout));
    putHead(header, *this, seq);
    header.put(",\"time_samples\":");
    header.putInteger(timeSamples);
    header.put(",\"variables\":[");
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (i) header.put(',');
        header.put("{\"name\":");
        header.put(layout->quotedNames[i]);
        header.put(",\"samples\":");
        header.putInteger(samples[i]);
        header.put('}');
    }
    header.put("]}");
    const std::string headerText = header.take();

    const auto headerBytes = static_cast<std::uint32_t>(headerText.size());
    const std::size_t dataOffset = (4 + headerText.size() + 7) / 8 * 8;
    std::string message(dataOffset + valueCount(parts) * sizeof(double), '\0');
    std::memcpy(message.data(), &headerBytes, 4);
    std::memcpy(message.data() + 4, headerText.data(), headerText.size());
    char* at = message.data() + dataOffset;
    auto putColumn = [&](auto values) {
        for (const auto& part : parts) {
            const std::vector<double>& v = values(*part);
            if (v.empty()) continue;
            std::memcpy(at, v.data(), v.size() * sizeof(double));
            at += v.size() * sizeof(double);
        }
    };
    putColumn([](const FrameSamples& s) -> const std::vector<double>& { return s.time; });
    for (std::size_t i = 0; i < samples.size(); ++i)
        putColumn([i](const FrameSamples& s) -> const std::vector<double>& { return columnOf(s, i); });
    return message;
}

} // namespace tlmhub::server
