#pragma once
// The samples of one event.frame as numbers: a time vector and one column per streamed
// variable. A frame stays data until it is written, so frames a slow connection cannot send
// yet are merged (appended) instead of dropped. A column may be a little shorter than the
// time vector in one frame (its log lags by a sample); concatenated, they all match the
// stored result.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tlmhub::server {

struct StreamFrame {
    std::int64_t jobId = 0;
    std::shared_ptr<const std::vector<std::string>> names;   // the subscription's variables
    std::vector<double> time;
    std::vector<std::vector<double>> columns;                // columns[i]: samples of (*names)[i]
    std::uint64_t merged = 0;                                // frames merged into this one

    // Appends the next frame of the same subscription.
    void append(StreamFrame&& later);
    // At least the size of toJson(seq)'s text.
    std::size_t textBytesBound() const;
    // event.frame; `dropped` is the number of frames merged into this one.
    nlohmann::json toJson(std::uint64_t seq) const;
};

} // namespace tlmhub::server
