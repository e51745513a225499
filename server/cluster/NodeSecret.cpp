#include "server/cluster/NodeSecret.h"

#include "server/auth/Sodium.h"

#include <sodium.h>
#include <sys/stat.h>

#include <array>
#include <fstream>
#include <sstream>
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
    const std::string where = "node secret file " + path.string();
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) throw std::runtime_error(where + ": cannot be read");
    // Anyone who can read the secret can act as a node and follow every user's jobs.
    if ((info.st_mode & (S_IRGRP | S_IROTH)) != 0) {
        std::ostringstream mode;
        mode << std::oct << (info.st_mode & 0777);
        throw std::runtime_error(where + " can be read by group or others (mode 0" + mode.str() +
                                 "); make it private: chmod 600 " + path.string());
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(where + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return fromText(text.str());
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(where + ": " + e.what());
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
