#pragma once
// The server's requests to an OpenID provider (discovery, key set, token endpoint) or a
// learning platform (key set, token endpoint, grade services): https
// only, the certificate verified against the system's CAs or the administrator's CA file,
// bounded in time (5 s to connect, 5 s for each wait) and size (1 MiB), one connection per
// request. Every failure is a message naming the address and why, never an exception.
#include "server/auth/oidc/JsonWebKeySet.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tlmhub::server {

struct ProviderReply {
    int status = 0;
    nlohmann::json body;   // the reply parsed as JSON (providers answer errors in JSON too)
};

class ProviderHttp {
public:
    explicit ProviderHttp(std::filesystem::path caFile = {});

    // GET `url`, which must be https; nullopt with `error` when there is no JSON reply.
    std::optional<ProviderReply> getJson(const std::string& url, std::string& error) const;
    // The key set at `url` (a provider's or a platform's), parsed; nullopt with `error`.
    std::optional<JsonWebKeySet> getKeySet(const std::string& url, std::string& error) const;
    // POST `form` (application/x-www-form-urlencoded) to `url` with more header fields.
    std::optional<ProviderReply> postForm(const std::string& url, const std::string& form,
                                          const std::vector<std::pair<std::string, std::string>>& headers,
                                          std::string& error) const;

    // POST `body` of `contentType` (a learning platform's grade services); the reply's body is
    // null when it is empty or not JSON.
    std::optional<ProviderReply> post(const std::string& url, const std::string& contentType, const std::string& body,
                                      const std::vector<std::pair<std::string, std::string>>& headers,
                                      std::string& error) const;

    static constexpr std::size_t kMaxReplyBytes = 1 << 20;

private:
    std::optional<ProviderReply> send(const std::string& url, bool post, const std::string& contentType,
                                      const std::string& content,
                                      const std::vector<std::pair<std::string, std::string>>& headers, bool needsJson,
                                      std::string& error) const;

    std::filesystem::path mCaFile;
};

} // namespace tlmhub::server
