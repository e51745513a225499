#include "server/store/JobLeaseStore.h"

#include <algorithm>

namespace tlmhub::server {

std::chrono::milliseconds leaseBackoff(std::int64_t claims, std::chrono::milliseconds backoff,
                                       std::chrono::milliseconds maxBackoff)
{
    // Doubled one claim at a time and stopped at the cap, so a large count cannot overflow.
    auto delay = std::max(backoff, std::chrono::milliseconds(0));
    for (std::int64_t i = 1; i < claims && delay < maxBackoff; ++i) delay *= 2;
    return std::min(delay, maxBackoff);
}

std::string deadLeaseError(std::int64_t claims, const std::string& lastNode)
{
    return "its node stopped answering " + std::to_string(claims) + " times; last node " + lastNode;
}

} // namespace tlmhub::server
