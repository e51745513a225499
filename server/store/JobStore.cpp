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

} // namespace tlmhub::server
