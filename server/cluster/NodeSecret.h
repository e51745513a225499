#pragma once
// The secret nodes of one deployment share, so that an API node may open a WebSocket to a
// worker node on behalf of its clients (server/cluster/RemoteJobStream.h). A node sends it
// as `Authorization: Bearer tlmhub-node.<secret>`; a connection that shows it is a node, not
// a user, and may only follow jobs (log.subscribe). The file is read once at start-up
// (--node-secret-file) and must be as private as a key: readable by its owner only.
#include <filesystem>
#include <string>
#include <string_view>

namespace tlmhub::server {

class NodeSecret {
public:
    static constexpr std::size_t kMinBytes = 32;
    static constexpr std::string_view kTokenPrefix = "tlmhub-node.";

    // Reads `path`. Throws std::runtime_error saying what is wrong (cannot read it, readable
    // by group or others, shorter than kMinBytes after a final newline is trimmed, or holds
    // a byte that cannot go in an HTTP header: control characters, spaces, non-ASCII).
    static NodeSecret load(const std::filesystem::path& path);
    // The same checks but the file's mode (tests; a secret that came from elsewhere).
    static NodeSecret fromText(std::string secret);

    // "tlmhub-node.<secret>", the Bearer token a node sends.
    std::string bearerToken() const;
    // Whether `token` is bearerToken(), in time that depends on neither its content nor
    // its length (both sides are hashed, then compared with sodium_memcmp).
    bool matches(std::string_view token) const;

private:
    explicit NodeSecret(std::string secret) : mSecret(std::move(secret)) {}
    std::string mSecret;
};

} // namespace tlmhub::server
