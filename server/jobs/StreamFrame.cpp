#include "server/jobs/StreamFrame.h"

namespace tlmhub::server {

namespace {

// The longest number nlohmann writes for a finite double, with its comma:
// "-2.2250738585072014e-308,".
constexpr std::size_t kNumberBytes = 25;
// Everything but the numbers and names: keys, ids, brackets.
constexpr std::size_t kFrameOverheadBytes = 128;

} // namespace

void StreamFrame::append(StreamFrame&& later)
{
    time.insert(time.end(), later.time.begin(), later.time.end());
    columns.resize(std::max(columns.size(), later.columns.size()));
    for (std::size_t i = 0; i < later.columns.size(); ++i)
        columns[i].insert(columns[i].end(), later.columns[i].begin(), later.columns[i].end());
    merged += later.merged + 1;
}

std::size_t StreamFrame::textBytesBound() const
{
    std::size_t bytes = kFrameOverheadBytes + time.size() * kNumberBytes;
    for (const auto& column : columns) bytes += column.size() * kNumberBytes;
    if (names)
        for (const auto& name : *names) bytes += 6 * name.size() + 4;   // quoted; a byte escapes to at most 6
    return bytes;
}

nlohmann::json StreamFrame::toJson(std::uint64_t seq) const
{
    nlohmann::json variables = nlohmann::json::object();
    for (std::size_t i = 0; names && i < names->size(); ++i)
        variables[(*names)[i]] = i < columns.size() ? columns[i] : std::vector<double>{};
    return {{"type", "event.frame"},
            {"job_id", jobId},
            {"seq", seq},
            {"time", time},
            {"variables", std::move(variables)},
            {"dropped", merged}};
}

} // namespace tlmhub::server
