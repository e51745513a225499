#pragma once
// Parsing JSON that arrives from a client. Nesting is bounded while parsing (nothing is built
// for a document that is too deep), since every later walk over the value (schema checks,
// serialising an echoed id, destruction) recurses once per level.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace tlmhub::server {

// Deeper than any message or body of the protocol needs (models nest a handful of levels).
inline constexpr std::size_t kMaxJsonDepth = 64;

struct UntrustedJson {
    nlohmann::json value;   // discarded unless ok()
    std::string error;      // what is wrong, in words (the protocol's code is bad_json)
    bool ok() const { return error.empty(); }
};

UntrustedJson parseUntrustedJson(std::string_view text, std::size_t maxDepth = kMaxJsonDepth);

} // namespace tlmhub::server
