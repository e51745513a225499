#include "server/jobs/StorageQuota.h"

#include <cstdio>

namespace tlmhub::server {

std::string byteSize(std::size_t bytes)
{
    constexpr double kKiB = 1024.0, kMiB = kKiB * 1024, kGiB = kMiB * 1024;
    const double b = static_cast<double>(bytes);
    char text[64];
    if (bytes < 1024) std::snprintf(text, sizeof text, "%zu bytes", bytes);
    else if (b < kMiB) std::snprintf(text, sizeof text, "%.1f KiB", b / kKiB);
    else if (b < kGiB) std::snprintf(text, sizeof text, "%.2f MiB", b / kMiB);
    else std::snprintf(text, sizeof text, "%.2f GiB", b / kGiB);
    return text;
}

std::string quotaMessage(std::size_t stored, std::size_t quota)
{
    return "your stored results use " + byteSize(stored) + " of " + byteSize(quota) +
           " (--max-stored-bytes-per-user); delete old jobs or studies first";
}

} // namespace tlmhub::server
