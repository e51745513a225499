#include "server/auth/lti/ToolKeys.h"

#include "server/auth/SecretFile.h"
#include "server/auth/oidc/Base64Url.h"

#include <openssl/bn.h>
#include <openssl/core_names.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/sha.h>

#include <stdexcept>

namespace tlmhub::server {

namespace {

constexpr int kMinToolKeyBits = 2048;

// A big number parameter of `key` (its modulus or exponent) as base64url of its bytes.
std::string keyNumber(EVP_PKEY* key, const char* name)
{
    BIGNUM* number = nullptr;
    if (EVP_PKEY_get_bn_param(key, name, &number) != 1) throw std::runtime_error("cannot read the RSA key's numbers");
    std::string bytes(static_cast<std::size_t>(BN_num_bytes(number)), '\0');
    BN_bn2bin(number, reinterpret_cast<unsigned char*>(bytes.data()));
    BN_free(number);
    return encodeBase64Url(bytes);
}

std::shared_ptr<EVP_PKEY> readPrivateKey(const std::string& file)
{
    const std::string pem = readSecretFile(file, "LTI key file");
    const std::unique_ptr<BIO, int (*)(BIO*)> input(BIO_new_mem_buf(pem.data(), static_cast<int>(pem.size())), BIO_free);
    EVP_PKEY* key = input ? PEM_read_bio_PrivateKey(input.get(), nullptr, nullptr, nullptr) : nullptr;
    if (!key) throw std::runtime_error("LTI key file " + file + " holds no PEM private key");
    std::shared_ptr<EVP_PKEY> owned(key, EVP_PKEY_free);
    if (!EVP_PKEY_is_a(key, "RSA") || EVP_PKEY_get_bits(key) < kMinToolKeyBits)
        throw std::runtime_error("LTI key file " + file + " must hold an RSA key of at least 2048 bits" +
                                 " (openssl genpkey -algorithm RSA -pkeyopt rsa_keygen_bits:2048)");
    return owned;
}

} // namespace

ToolKeys::ToolKeys(const std::vector<std::string>& files)
{
    if (files.empty()) throw std::runtime_error("the LTI tool needs a key file (--lti-key-file)");
    for (const std::string& file : files) {
        Key key;
        key.privateKey = readPrivateKey(file);
        const std::string n = keyNumber(key.privateKey.get(), OSSL_PKEY_PARAM_RSA_N);
        const std::string e = keyNumber(key.privateKey.get(), OSSL_PKEY_PARAM_RSA_E);
        // RFC 7638: the hash of the required members, in this order, without spaces.
        const std::string canonical = R"({"e":")" + e + R"(","kty":"RSA","n":")" + n + R"("})";
        unsigned char digest[SHA256_DIGEST_LENGTH];
        SHA256(reinterpret_cast<const unsigned char*>(canonical.data()), canonical.size(), digest);
        key.id = encodeBase64Url(std::string_view(reinterpret_cast<const char*>(digest), sizeof digest));
        key.publicJwk = {{"kty", "RSA"}, {"n", n}, {"e", e}, {"kid", key.id}, {"alg", "RS256"}, {"use", "sig"}};
        mKeys.push_back(std::move(key));
    }
}

nlohmann::json ToolKeys::keySet() const
{
    nlohmann::json keys = nlohmann::json::array();
    for (const Key& key : mKeys) keys.push_back(key.publicJwk);
    return {{"keys", std::move(keys)}};
}

std::string ToolKeys::sign(const nlohmann::json& claims) const
{
    const Key& key = mKeys.front();
    const nlohmann::json header = {{"alg", "RS256"}, {"typ", "JWT"}, {"kid", key.id}};
    const std::string input = encodeBase64Url(header.dump()) + "." + encodeBase64Url(claims.dump());
    const std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
    std::size_t length = 0;
    if (!context || EVP_DigestSignInit(context.get(), nullptr, EVP_sha256(), nullptr, key.privateKey.get()) != 1 ||
        EVP_DigestSign(context.get(), nullptr, &length, reinterpret_cast<const unsigned char*>(input.data()),
                       input.size()) != 1)
        throw std::runtime_error("cannot sign with the LTI key");
    std::string signature(length, '\0');
    if (EVP_DigestSign(context.get(), reinterpret_cast<unsigned char*>(signature.data()), &length,
                       reinterpret_cast<const unsigned char*>(input.data()), input.size()) != 1)
        throw std::runtime_error("cannot sign with the LTI key");
    signature.resize(length);
    return input + "." + encodeBase64Url(signature);
}

} // namespace tlmhub::server
