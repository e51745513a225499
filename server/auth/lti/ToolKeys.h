#pragma once
// The LTI tool's own signing keys (--lti-key-file, repeatable): RSA private keys of 2048 bits or
// more in PEM files that only the server's user may read. The first signs what the tool sends
// a platform (deep-linking answers, grade-service token requests); all are published in the
// tool's key set, so a platform can still check what was signed before a rotation. Rotating:
// add the new key's file first and restart, then, once platforms have fetched the set again,
// drop the old one.
#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

typedef struct evp_pkey_st EVP_PKEY;

namespace tlmhub::server {

class ToolKeys {
public:
    // Throws std::runtime_error naming the file when it cannot be read, may be read by others,
    // or holds no RSA private key of at least 2048 bits; also when `files` is empty.
    explicit ToolKeys(const std::vector<std::string>& files);

    // {"keys": [public JWKs with kid, alg RS256, use sig]}, the signing key first.
    nlohmann::json keySet() const;
    // A compact JWS of `claims`, RS256 with the signing key, its kid in the header.
    std::string sign(const nlohmann::json& claims) const;
    const std::string& signingKeyId() const { return mKeys.front().id; }

private:
    struct Key {
        std::shared_ptr<EVP_PKEY> privateKey;
        nlohmann::json publicJwk;
        std::string id;   // the RFC 7638 thumbprint: the same key keeps its id across restarts
    };
    std::vector<Key> mKeys;
};

} // namespace tlmhub::server
