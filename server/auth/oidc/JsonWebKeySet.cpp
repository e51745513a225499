#include "server/auth/oidc/JsonWebKeySet.h"

#include "server/auth/oidc/Base64Url.h"
#include "server/auth/oidc/JsonMembers.h"

#include <openssl/bn.h>
#include <openssl/core_names.h>
#include <openssl/evp.h>
#include <openssl/param_build.h>

#include <algorithm>

namespace tlmhub::server {

namespace {

constexpr int kMinRsaBits = 2048;

template <typename T, void (*Free)(T*)>
struct Freeing {
    void operator()(T* p) const { Free(p); }
};
using ParamBuilder = std::unique_ptr<OSSL_PARAM_BLD, Freeing<OSSL_PARAM_BLD, OSSL_PARAM_BLD_free>>;
using Params = std::unique_ptr<OSSL_PARAM, Freeing<OSSL_PARAM, OSSL_PARAM_free>>;
using KeyContext = std::unique_ptr<EVP_PKEY_CTX, Freeing<EVP_PKEY_CTX, EVP_PKEY_CTX_free>>;
using BigNumber = std::unique_ptr<BIGNUM, Freeing<BIGNUM, BN_free>>;

// A member holding base64url bytes (a key's number or coordinate); nullopt when missing or not.
std::optional<std::string> bytesMember(const nlohmann::json& object, const char* name)
{
    const std::string text = stringMember(object, name);
    if (text.empty()) return std::nullopt;
    return decodeBase64Url(text);
}

// An OpenSSL public key from `params` of key type `type`, checked; null when it is not one.
std::shared_ptr<EVP_PKEY> publicKeyFrom(const char* type, OSSL_PARAM_BLD* builder)
{
    const Params params(OSSL_PARAM_BLD_to_param(builder));
    const KeyContext context(EVP_PKEY_CTX_new_from_name(nullptr, type, nullptr));
    EVP_PKEY* key = nullptr;
    if (!params || !context || EVP_PKEY_fromdata_init(context.get()) != 1 ||
        EVP_PKEY_fromdata(context.get(), &key, EVP_PKEY_PUBLIC_KEY, params.get()) != 1)
        return nullptr;
    std::shared_ptr<EVP_PKEY> owned(key, EVP_PKEY_free);
    const KeyContext check(EVP_PKEY_CTX_new_from_pkey(nullptr, key, nullptr));
    if (!check || EVP_PKEY_public_check(check.get()) != 1) return nullptr;
    return owned;
}

std::shared_ptr<EVP_PKEY> rsaKey(const nlohmann::json& jwk)
{
    const auto modulus = bytesMember(jwk, "n");
    const auto exponent = bytesMember(jwk, "e");
    if (!modulus || !exponent) return nullptr;
    const BigNumber n(BN_bin2bn(reinterpret_cast<const unsigned char*>(modulus->data()), int(modulus->size()), nullptr));
    const BigNumber e(BN_bin2bn(reinterpret_cast<const unsigned char*>(exponent->data()), int(exponent->size()), nullptr));
    const ParamBuilder builder(OSSL_PARAM_BLD_new());
    if (!n || !e || !builder || OSSL_PARAM_BLD_push_BN(builder.get(), OSSL_PKEY_PARAM_RSA_N, n.get()) != 1 ||
        OSSL_PARAM_BLD_push_BN(builder.get(), OSSL_PKEY_PARAM_RSA_E, e.get()) != 1)
        return nullptr;
    auto key = publicKeyFrom("RSA", builder.get());
    if (key && EVP_PKEY_get_bits(key.get()) < kMinRsaBits) return nullptr;
    return key;
}

std::shared_ptr<EVP_PKEY> ecKey(const nlohmann::json& jwk, const std::string& crv)
{
    const std::size_t coordinateBytes = crv == "P-256" ? 32 : crv == "P-384" ? 48 : 0;
    const auto x = bytesMember(jwk, "x");
    const auto y = bytesMember(jwk, "y");
    if (coordinateBytes == 0 || !x || !y || x->size() != coordinateBytes || y->size() != coordinateBytes)
        return nullptr;
    std::string point = "\x04" + *x + *y;   // uncompressed (SEC 1 §2.3.3)
    std::string group = crv == "P-256" ? "prime256v1" : "secp384r1";
    const ParamBuilder builder(OSSL_PARAM_BLD_new());
    if (!builder || OSSL_PARAM_BLD_push_utf8_string(builder.get(), OSSL_PKEY_PARAM_GROUP_NAME, group.data(), 0) != 1 ||
        OSSL_PARAM_BLD_push_octet_string(builder.get(), OSSL_PKEY_PARAM_PUB_KEY, point.data(), point.size()) != 1)
        return nullptr;
    return publicKeyFrom("EC", builder.get());
}

} // namespace

bool JsonWebKey::suits(const std::string& jwsAlg) const
{
    if (!alg.empty() && alg != jwsAlg) return false;
    if (kty == "RSA")
        return jwsAlg == "RS256" || jwsAlg == "RS384" || jwsAlg == "RS512" || jwsAlg == "PS256" || jwsAlg == "PS384" ||
               jwsAlg == "PS512";
    if (kty == "EC") return (jwsAlg == "ES256" && crv == "P-256") || (jwsAlg == "ES384" && crv == "P-384");
    return false;
}

std::optional<JsonWebKeySet> JsonWebKeySet::parse(const nlohmann::json& document, std::string& error)
{
    const auto keys = document.is_object() ? document.find("keys") : document.end();
    if (!document.is_object() || keys == document.end() || !keys->is_array()) {
        error = "the provider's key set is not a JSON Web Key Set ({\"keys\": [...]})";
        return std::nullopt;
    }
    JsonWebKeySet set;
    for (const nlohmann::json& jwk : *keys) {
        if (!jwk.is_object()) continue;
        const std::string use = stringMember(jwk, "use");
        if (!use.empty() && use != "sig") continue;
        if (const auto ops = jwk.find("key_ops"); ops != jwk.end() &&
            (!ops->is_array() || std::find(ops->begin(), ops->end(), nlohmann::json("verify")) == ops->end()))
            continue;
        JsonWebKey key{stringMember(jwk, "kid"), stringMember(jwk, "kty"), stringMember(jwk, "crv"),
                       stringMember(jwk, "alg"), nullptr};
        if (key.kty == "RSA") key.key = rsaKey(jwk);
        else if (key.kty == "EC") key.key = ecKey(jwk, key.crv);
        if (key.key) set.mKeys.push_back(std::move(key));
    }
    if (set.mKeys.empty()) {
        error = "the provider's key set has no RSA (2048 bits or more) or P-256/P-384 signing key";
        return std::nullopt;
    }
    return set;
}

const JsonWebKey* JsonWebKeySet::find(const std::string& kid, const std::string& alg) const
{
    const JsonWebKey* found = nullptr;
    for (const JsonWebKey& key : mKeys) {
        if (!kid.empty() ? key.kid != kid : !key.suits(alg)) continue;
        if (found) return nullptr;   // ambiguous: a provider's kids should be unique
        found = &key;
    }
    return found && found->suits(alg) ? found : nullptr;
}

} // namespace tlmhub::server
