#pragma once
// Short-lived signed links for downloads a browser starts itself (an <a href> cannot send
// an Authorization header). A link names one GET target, one user and the login it was made
// in (its session key: the link ends with that login), expires after `ttl`, and is signed
// with a key that lives only in this process (links die with a restart).
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
    Link sign(const std::string& target, std::int64_t userId, const std::string& sessionKey) const;
    struct Signer {
        std::int64_t userId;
        std::string sessionKey;
    };
    // Whom a request target's `download` parameter was signed for, when the signature
    // matches this very target and has not expired. The caller checks the login still lives.
    std::optional<Signer> verify(const std::string& targetWithLink) const;
    // Empty when `target` is a download a link may open (results, a model's file, an FMU, a
    // gradebook, a hand-in's model), else why not.
    static std::string targetProblem(const std::string& target);

    static constexpr const char* kParameter = "download";

private:
    std::string mac(const std::string& target, std::int64_t userId, std::int64_t expiresAt,
                    const std::string& sessionKey) const;

    std::chrono::seconds mTtl;
    std::string mKey;
};

} // namespace tlmhub::server
