#include "server/store/JobStore.h"

namespace tlmhub::server {

std::optional<JobRequest> JobStore::request(std::int64_t id)
{
    const auto text = requestText(id);
    if (!text) return std::nullopt;
    const auto json = nlohmann::json::parse(*text, nullptr, false);
    JobRequest r;
    if (json.is_discarded() || !JobRequest::fromJson(json, r)) return std::nullopt;
    return r;
}

std::map<std::string, std::string> JobStore::parameterOverrides(const std::string& json)
{
    const auto parsed = nlohmann::json::parse(json, nullptr, false);
    std::map<std::string, std::string> out;
    if (!parsed.is_object()) return out;
    for (const auto& [name, value] : parsed.items())
        if (value.is_string()) out[name] = value.get<std::string>();
    return out;
}

} // namespace tlmhub::server
