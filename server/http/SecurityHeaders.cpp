#include "server/http/SecurityHeaders.h"

namespace tlmhub::server {

const char* const kContentSecurityPolicyWithoutFrameAncestors =
    "default-src 'self'; script-src 'self'; object-src 'none'; base-uri 'none'";
const char* const kContentSecurityPolicy =
    "default-src 'self'; script-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'self'";

void addSecurityHeaders(Response& response)
{
    // By name: Beast's field enumeration has none of these.
    const auto setIfAbsent = [&](const char* name, const char* value) {
        if (response.find(name) == response.end()) response.set(name, value);
    };
    setIfAbsent("Content-Security-Policy", kContentSecurityPolicy);
    setIfAbsent("X-Content-Type-Options", "nosniff");
    setIfAbsent("Referrer-Policy", "no-referrer");
}

} // namespace tlmhub::server
