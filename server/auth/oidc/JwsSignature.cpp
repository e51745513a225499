#include "server/auth/oidc/JwsSignature.h"

#include <openssl/bn.h>
#include <openssl/ecdsa.h>
#include <openssl/evp.h>
#include <openssl/rsa.h>

#include <memory>

namespace tlmhub::server {

namespace {

const EVP_MD* digestOf(const std::string& alg)
{
    const std::string bits = alg.size() == 5 ? alg.substr(2) : std::string{};
    if (bits == "256") return EVP_sha256();
    if (bits == "384") return EVP_sha384();
    if (bits == "512") return EVP_sha512();
    return nullptr;
}

// JWS carries an ECDSA signature as r and s side by side, each the curve's size (RFC 7518
// §3.4); OpenSSL checks the DER form.
std::string ecdsaDer(std::string_view raw, std::size_t coordinateBytes)
{
    if (raw.size() != 2 * coordinateBytes) return {};
    const auto* bytes = reinterpret_cast<const unsigned char*>(raw.data());
    std::unique_ptr<ECDSA_SIG, decltype(&ECDSA_SIG_free)> signature(ECDSA_SIG_new(), ECDSA_SIG_free);
    BIGNUM* r = BN_bin2bn(bytes, int(coordinateBytes), nullptr);
    BIGNUM* s = BN_bin2bn(bytes + coordinateBytes, int(coordinateBytes), nullptr);
    if (!signature || !r || !s || ECDSA_SIG_set0(signature.get(), r, s) != 1) {
        BN_free(r);
        BN_free(s);
        return {};
    }
    unsigned char* der = nullptr;
    const int length = i2d_ECDSA_SIG(signature.get(), &der);
    if (length <= 0) return {};
    std::string out(reinterpret_cast<char*>(der), std::size_t(length));
    OPENSSL_free(der);
    return out;
}

} // namespace

bool isSupportedJwsAlgorithm(const std::string& alg)
{
    return alg == "RS256" || alg == "RS384" || alg == "RS512" || alg == "PS256" || alg == "PS384" || alg == "PS512" ||
           alg == "ES256" || alg == "ES384";
}

bool verifyJwsSignature(const JsonWebKey& key, const std::string& alg, std::string_view signingInput,
                        std::string_view signature)
{
    if (!isSupportedJwsAlgorithm(alg) || !key.suits(alg) || !key.key) return false;
    std::string der;
    if (alg.starts_with("ES")) {
        der = ecdsaDer(signature, alg == "ES256" ? 32 : 48);
        if (der.empty()) return false;
        signature = der;
    }
    std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
    EVP_PKEY_CTX* keyContext = nullptr;   // owned by `context`
    if (!context || EVP_DigestVerifyInit(context.get(), &keyContext, digestOf(alg), nullptr, key.key.get()) != 1)
        return false;
    if (alg.starts_with("PS") && (EVP_PKEY_CTX_set_rsa_padding(keyContext, RSA_PKCS1_PSS_PADDING) != 1 ||
                                  EVP_PKEY_CTX_set_rsa_pss_saltlen(keyContext, RSA_PSS_SALTLEN_DIGEST) != 1))
        return false;
    if (alg.starts_with("RS") && EVP_PKEY_CTX_set_rsa_padding(keyContext, RSA_PKCS1_PADDING) != 1) return false;
    return EVP_DigestVerify(context.get(), reinterpret_cast<const unsigned char*>(signature.data()), signature.size(),
                            reinterpret_cast<const unsigned char*>(signingInput.data()), signingInput.size()) == 1;
}

} // namespace tlmhub::server
