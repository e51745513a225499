#pragma once
// JSON text for clients. Messages echo client input (a request path, a name from an uploaded
// .hmf) that need not be valid UTF-8, where nlohmann's dump() throws; such bytes become
// U+FFFD instead, so every reply can still be written.
#include <nlohmann/json.hpp>

#include <string>

namespace tlmhub::server {

inline std::string toJsonText(const nlohmann::json& value)
{
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace tlmhub::server
