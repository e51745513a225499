#include "server/cluster/NodeSecret.h"

#include "server/auth/SecretFile.h"
#include "server/auth/Sodium.h"

#include <sodium.h>

#include <array>
#include <stdexcept>

namespace tlmhub::server {

namespace {

using Digest = std::array<unsigned char, crypto_generichash_BYTES>;

Digest digest(std::string_view text)
{
    Digest d{};
    crypto_generichash(d.data(), d.size(), reinterpret_cast<const unsigned char*>(text.data()), text.size(),
                       nullptr, 0);
    return d;
}

} // namespace

NodeSecret NodeSecret::load(const std::filesystem::path& path)
{
    // Anyone who can read the secret can act as a node and follow every user's jobs.
    const std::string secret = readSecretFile(path, "node secret file");
    try {
        return fromText(secret);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("node secret file " + path.string() + ": " + e.what());
    }
}

NodeSecret NodeSecret::fromText(std::string secret)
{
    // Editors and `echo` end a file with a newline; it is not part of the secret.
    if (!secret.empty() && secret.back() == '\n') secret.pop_back();
    if (!secret.empty() && secret.back() == '\r') secret.pop_back();
    if (secret.size() < kMinBytes)
        throw std::runtime_error("the secret has " + std::to_string(secret.size()) + " bytes, fewer than " +
                                 std::to_string(kMinBytes) + " (e.g. openssl rand -hex 32)");
    for (unsigned char c : secret)
        if (c <= 0x20 || c >= 0x7f)
            throw std::runtime_error("the secret may hold printable ASCII only (no spaces): it is sent in an "
                                     "HTTP header");
    ensureSodium();
    return NodeSecret(std::move(secret));
}

std::string NodeSecret::bearerToken() const
{
    return std::string(kTokenPrefix) + mSecret;
}

bool NodeSecret::matches(std::string_view token) const
{
    const Digest expected = digest(bearerToken());
    const Digest given = digest(token);
    return sodium_memcmp(expected.data(), given.data(), expected.size()) == 0;
}

} // namespace tlmhub::server
