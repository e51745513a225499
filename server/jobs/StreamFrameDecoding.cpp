#include "server/jobs/StreamFrameDecoding.h"

#include "server/protocol/UntrustedJson.h"

#include <bit>
#include <cstdint>
#include <limits>
#include <cstring>
#include <set>

namespace tlmhub::server {

namespace {

static_assert(std::endian::native == std::endian::little,
              "binary frames hold float64 samples as they lie in memory");

bool fail(std::string& error, std::string what)
{
    error = "binary event.frame: " + std::move(what);
    return false;
}

// An unsigned integer field: the protocol's counts and ids are JSON integers, never floats.
bool readCount(const nlohmann::json& object, const char* key, std::uint64_t& out, std::string& error)
{
    const auto it = object.find(key);
    if (it == object.end()) return fail(error, std::string("header has no '") + key + "'");
    if (it->is_number_unsigned()) {
        out = it->get<std::uint64_t>();
        return true;
    }
    if (it->is_number_integer() && it->get<std::int64_t>() >= 0) {
        out = static_cast<std::uint64_t>(it->get<std::int64_t>());
        return true;
    }
    return fail(error, std::string("header's '") + key + "' is not a non-negative integer");
}

bool onlyKeys(const nlohmann::json& object, std::initializer_list<const char*> keys, const char* what,
              std::string& error)
{
    for (const auto& [key, value] : object.items()) {
        bool known = false;
        for (const char* k : keys) known = known || key == k;
        if (!known) return fail(error, std::string(what) + " has an unknown key '" + key.substr(0, 64) + "'");
    }
    return true;
}

} // namespace

bool decodeBinaryFrame(std::string_view message, DecodedFrame& out, std::string& error)
{
    if (message.size() < 4) return fail(error, "shorter than its header length");
    std::uint32_t headerBytes = 0;
    std::memcpy(&headerBytes, message.data(), 4);
    if (headerBytes > message.size() - 4) return fail(error, "header length past the end of the message");
    const std::size_t dataOffset = (4 + std::size_t{headerBytes} + 7) / 8 * 8;
    if (dataOffset > message.size()) return fail(error, "message ends in the header's padding");
    for (std::size_t i = 4 + headerBytes; i < dataOffset; ++i)
        if (message[i] != '\0') return fail(error, "padding after the header is not zero");

    // Names and counts only: two levels deep.
    const UntrustedJson parsed = parseUntrustedJson(message.substr(4, headerBytes), 4);
    if (!parsed.ok()) return fail(error, "header: " + parsed.error);
    const nlohmann::json& header = parsed.value;
    if (!header.is_object()) return fail(error, "header is not an object");
    if (!onlyKeys(header, {"type", "job_id", "seq", "dropped", "time_samples", "variables"}, "header", error))
        return false;
    const auto type = header.find("type");
    if (type == header.end() || !type->is_string() || type->get<std::string>() != "event.frame")
        return fail(error, "header's type is not event.frame");
    std::uint64_t jobId = 0, seq = 0, dropped = 0, timeSamples = 0;
    if (!readCount(header, "job_id", jobId, error) || !readCount(header, "seq", seq, error) ||
        !readCount(header, "dropped", dropped, error) || !readCount(header, "time_samples", timeSamples, error))
        return false;
    if (jobId == 0 || jobId > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return fail(error, "header's job_id is out of range");
    const auto variables = header.find("variables");
    if (variables == header.end() || !variables->is_array()) return fail(error, "header's variables is not an array");

    // Every count is checked against the bytes left before it is added, so the sum cannot
    // overflow and nothing is allocated beyond the message's own size.
    const std::size_t valuesInMessage = (message.size() - dataOffset) / sizeof(double);
    if ((message.size() - dataOffset) % sizeof(double) != 0) return fail(error, "samples are not whole float64s");
    std::size_t values = 0;
    auto addCount = [&](std::uint64_t n) {
        if (n > valuesInMessage - values) return false;
        values += static_cast<std::size_t>(n);
        return true;
    };
    if (!addCount(timeSamples)) return fail(error, "time_samples is more than the message holds");
    std::vector<std::string> names;
    std::vector<std::size_t> counts;
    std::set<std::string> seen;
    for (const auto& v : *variables) {
        if (!v.is_object()) return fail(error, "a variable is not an object");
        if (!onlyKeys(v, {"name", "samples"}, "a variable", error)) return false;
        const auto name = v.find("name");
        if (name == v.end() || !name->is_string()) return fail(error, "a variable's name is not a string");
        std::uint64_t samples = 0;
        if (!readCount(v, "samples", samples, error)) return false;
        if (!addCount(samples)) return fail(error, "a variable's samples are more than the message holds");
        if (!seen.insert(name->get<std::string>()).second) return fail(error, "a variable is named twice");
        names.push_back(name->get<std::string>());
        counts.push_back(static_cast<std::size_t>(samples));
    }
    if (values != valuesInMessage) return fail(error, "the message holds more samples than its header counts");

    auto samples = std::make_shared<FrameSamples>();
    const char* at = message.data() + dataOffset;
    auto take = [&at](std::size_t n, std::vector<double>& to) {
        to.resize(n);
        if (n) std::memcpy(to.data(), at, n * sizeof(double));
        at += n * sizeof(double);
    };
    take(static_cast<std::size_t>(timeSamples), samples->time);
    samples->columns.resize(counts.size());
    for (std::size_t i = 0; i < counts.size(); ++i) take(counts[i], samples->columns[i]);

    out.seq = seq;
    out.dropped = dropped;
    out.frame = StreamFrame{};
    out.frame.jobId = static_cast<std::int64_t>(jobId);
    out.frame.layout = std::make_shared<const FrameLayout>(std::move(names));
    out.frame.parts.push_back(std::move(samples));
    return true;
}

} // namespace tlmhub::server
