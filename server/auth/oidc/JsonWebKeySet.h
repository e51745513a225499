#pragma once
// An OpenID provider's signing keys: the JSON Web Key Set (RFC 7517) its `jwks_uri` serves,
// as OpenSSL public keys by key id. Only RSA keys of 2048 bits or more and EC keys on P-256 or
// P-384 meant for signatures are kept; other keys are skipped (a provider may publish
// encryption keys beside them), so one odd key does not lose the others.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

typedef struct evp_pkey_st EVP_PKEY;

namespace tlmhub::server {

struct JsonWebKey {
    std::string kid;        // empty when the set gives none
    std::string kty;        // "RSA" or "EC"
    std::string crv;        // EC: "P-256" or "P-384"
    std::string alg;        // as published; empty when the key does not bind one
    std::shared_ptr<EVP_PKEY> key;

    // Whether this key may check a signature made with JWS algorithm `alg` (RS256 ... ES384).
    bool suits(const std::string& alg) const;
};

class JsonWebKeySet {
public:
    // nullopt with `error` when the document is not a key set ({"keys": [...]}) or holds no
    // usable signing key.
    static std::optional<JsonWebKeySet> parse(const nlohmann::json& document, std::string& error);

    // The key a token whose header has `kid` and `alg` must have been signed with: the one
    // with that id; without an id, the only key that suits `alg` (none when several do).
    const JsonWebKey* find(const std::string& kid, const std::string& alg) const;
    std::size_t size() const { return mKeys.size(); }

private:
    std::vector<JsonWebKey> mKeys;
};

} // namespace tlmhub::server
