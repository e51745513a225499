#pragma once
// Short-lived signed links for downloads a browser starts itself (an <a href> cannot send
// an Authorization header). A link names one GET target and one user, expires after `ttl`,
// and is signed with a key that lives only in this process (links die with a restart).
// This is the only way a REST call authenticates through the query string, so login tokens
// never end up in logs or browser history.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace tlmhub::server {

class DownloadLinks {
public:
    explicit DownloadLinks(std::chrono::seconds ttl);

    struct Link {
        std::string url;        // `target` with &download=... appended
        std::int64_t expiresAt; // unix seconds
    };
    // `target`: an API path with its query, e.g. "/api/v1/jobs/5/results?format=csv".
    Link sign(const std::string& target, std::int64_t userId) const;
    // The user a request target's `download` parameter was signed for, when the signature
    // matches this very target and has not expired.
    std::optional<std::int64_t> verify(const std::string& targetWithLink) const;

    static constexpr const char* kParameter = "download";

private:
    std::string mac(const std::string& target, std::int64_t userId, std::int64_t expiresAt) const;

    std::chrono::seconds mTtl;
    std::string mKey;
};

} // namespace tlmhub::server
