// Checking OpenID providers' ID tokens (issue 43 item 1, docs/sign-in.md): tokens signed by
// keys this test makes with OpenSSL, as a provider would, then each check the specification
// asks for failing on its own, keys rotated, and a provider that cannot be reached.
#include "server/auth/oidc/Base64Url.h"
#include "server/auth/oidc/IdTokenVerifier.h"
#include "server/auth/oidc/JsonWebKeySet.h"

#include <gtest/gtest.h>

#include <openssl/bn.h>
#include <openssl/core_names.h>
#include <openssl/ecdsa.h>
#include <openssl/evp.h>
#include <openssl/rsa.h>

#include <memory>

using namespace tlmhub::server;

namespace {

constexpr std::int64_t kNow = 1'800'000'000;
const std::string kIssuer = "https://login.example.edu/realms/staff";
const std::string kClient = "tlmhub";
const std::string kNonce = "n-0S6_WzA2Mj";

std::string bignumBytes(EVP_PKEY* key, const char* name)
{
    BIGNUM* number = nullptr;
    EXPECT_EQ(EVP_PKEY_get_bn_param(key, name, &number), 1);
    std::string bytes(std::size_t(BN_num_bytes(number)), '\0');
    BN_bn2bin(number, reinterpret_cast<unsigned char*>(bytes.data()));
    BN_free(number);
    return bytes;
}

// A provider's signing key: its private half signs, its public half is published as a JWK.
class SigningKey {
public:
    // "RSA" (2048 bits unless `bits`) or "EC" (P-256).
    explicit SigningKey(std::string kid, const std::string& type = "RSA", unsigned bits = 2048) : mKid(std::move(kid))
    {
        mKey.reset(type == "RSA" ? EVP_PKEY_Q_keygen(nullptr, nullptr, "RSA", std::size_t(bits))
                                 : EVP_PKEY_Q_keygen(nullptr, nullptr, "EC", "P-256"));
        if (!mKey) throw std::runtime_error("no key");
        mEc = type == "EC";
    }

    nlohmann::json jwk() const
    {
        if (!mEc)
            return {{"kty", "RSA"}, {"kid", mKid}, {"use", "sig"}, {"alg", "RS256"},
                    {"n", encodeBase64Url(bignumBytes(mKey.get(), OSSL_PKEY_PARAM_RSA_N))},
                    {"e", encodeBase64Url(bignumBytes(mKey.get(), OSSL_PKEY_PARAM_RSA_E))}};
        std::string x = bignumBytes(mKey.get(), OSSL_PKEY_PARAM_EC_PUB_X);
        std::string y = bignumBytes(mKey.get(), OSSL_PKEY_PARAM_EC_PUB_Y);
        x.insert(0, 32 - x.size(), '\0');
        y.insert(0, 32 - y.size(), '\0');
        return {{"kty", "EC"}, {"kid", mKid}, {"crv", "P-256"}, {"x", encodeBase64Url(x)}, {"y", encodeBase64Url(y)}};
    }

    // The compact JWS of `claims`; `header` members override the default ones.
    std::string sign(const nlohmann::json& claims, const nlohmann::json& header = nlohmann::json::object()) const
    {
        nlohmann::json h = {{"alg", mEc ? "ES256" : "RS256"}, {"typ", "JWT"}, {"kid", mKid}};
        h.update(header);
        const std::string input = encodeBase64Url(h.dump()) + "." + encodeBase64Url(claims.dump());
        return input + "." + encodeBase64Url(signature(input));
    }

private:
    std::string signature(const std::string& input) const
    {
        std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
        EXPECT_EQ(EVP_DigestSignInit(context.get(), nullptr, EVP_sha256(), nullptr, mKey.get()), 1);
        std::size_t length = 0;
        const auto* data = reinterpret_cast<const unsigned char*>(input.data());
        EXPECT_EQ(EVP_DigestSign(context.get(), nullptr, &length, data, input.size()), 1);
        std::string out(length, '\0');
        EXPECT_EQ(EVP_DigestSign(context.get(), reinterpret_cast<unsigned char*>(out.data()), &length, data, input.size()), 1);
        out.resize(length);
        if (!mEc) return out;
        // DER to JWS's r || s, 32 bytes each
        const auto* der = reinterpret_cast<const unsigned char*>(out.data());
        ECDSA_SIG* parsed = d2i_ECDSA_SIG(nullptr, &der, long(out.size()));
        std::string raw(64, '\0');
        BN_bn2binpad(ECDSA_SIG_get0_r(parsed), reinterpret_cast<unsigned char*>(raw.data()), 32);
        BN_bn2binpad(ECDSA_SIG_get0_s(parsed), reinterpret_cast<unsigned char*>(raw.data()) + 32, 32);
        ECDSA_SIG_free(parsed);
        return raw;
    }

    std::string mKid;
    bool mEc = false;
    std::unique_ptr<EVP_PKEY, decltype(&EVP_PKEY_free)> mKey{nullptr, EVP_PKEY_free};
};

nlohmann::json validClaims()
{
    return {{"iss", kIssuer}, {"sub", "248289761001"}, {"aud", kClient}, {"nonce", kNonce},
            {"iat", kNow - 5},  {"exp", kNow + 300},      {"name", "Jane Doe"}};
}

IdTokenExpectations expectations()
{
    return {kIssuer, kClient, kNonce, kNow};
}

// A provider whose published keys the test changes; counts how often they were fetched.
struct Provider {
    nlohmann::json published = {{"keys", nlohmann::json::array()}};
    bool reachable = true;
    int fetches = 0;

    ProviderKeyCache cache()
    {
        return ProviderKeyCache([this](std::string& error) -> std::optional<JsonWebKeySet> {
            ++fetches;
            if (!reachable) {
                error = "connect to login.example.edu:443: connection refused";
                return std::nullopt;
            }
            return JsonWebKeySet::parse(published, error);
        });
    }
};

// The code of the failure, or "" when the token was taken.
std::string refusal(const std::variant<IdToken, IdTokenError>& outcome)
{
    return std::holds_alternative<IdTokenError>(outcome) ? std::get<IdTokenError>(outcome).code : "";
}

class OidcIdTokens : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        sRsa = std::make_unique<SigningKey>("rsa-1");
        sEc = std::make_unique<SigningKey>("ec-1", "EC");
    }
    static void TearDownTestSuite()
    {
        sRsa.reset();
        sEc.reset();
    }
    void SetUp() override { provider.published["keys"] = {sRsa->jwk(), sEc->jwk()}; }

    static std::unique_ptr<SigningKey> sRsa, sEc;
    Provider provider;
};
std::unique_ptr<SigningKey> OidcIdTokens::sRsa, OidcIdTokens::sEc;

} // namespace

TEST_F(OidcIdTokens, ATokenSignedByAPublishedKeyGivesItsSubjectAndClaims)
{
    auto keys = provider.cache();
    for (const SigningKey* key : {sRsa.get(), sEc.get()}) {
        const auto outcome = verifyIdToken(key->sign(validClaims()), keys, expectations());
        ASSERT_EQ(refusal(outcome), "");
        EXPECT_EQ(std::get<IdToken>(outcome).subject, "248289761001");
        EXPECT_EQ(std::get<IdToken>(outcome).claims.at("name"), "Jane Doe");
    }
    EXPECT_EQ(provider.fetches, 1) << "the set is fetched once and kept";
}

TEST_F(OidcIdTokens, EachClaimCheckRefusesWithItsOwnCode)
{
    struct Case {
        const char* what;
        nlohmann::json change;   // merged into the valid claims (null removes)
        const char* code;
    };
    const std::vector<Case> cases = {
        {"another issuer", {{"iss", "https://evil.example.com"}}, "wrong_issuer"},
        {"the issuer with a trailing slash", {{"iss", kIssuer + "/"}}, "wrong_issuer"},
        {"no issuer", {{"iss", nullptr}}, "wrong_issuer"},
        {"another client", {{"aud", "someone-else"}}, "wrong_audience"},
        {"us among other audiences", {{"aud", {kClient, "someone-else"}}, {"azp", kClient}}, "wrong_audience"},
        {"no audience", {{"aud", nullptr}}, "wrong_audience"},
        {"given to another client", {{"azp", "someone-else"}}, "wrong_azp"},
        {"expired", {{"exp", kNow - 121}}, "expired"},
        {"issued in the future", {{"iat", kNow + 121}}, "issued_in_future"},
        {"issued long ago", {{"iat", kNow - 721}, {"exp", kNow + 300}}, "too_old"},
        {"not valid yet", {{"nbf", kNow + 121}}, "not_yet_valid"},
        {"no exp", {{"exp", nullptr}}, "malformed"},
        {"exp as text", {{"exp", "1900000000"}}, "malformed"},
        {"another sign-in's nonce", {{"nonce", "n-replayed"}}, "wrong_nonce"},
        {"no nonce", {{"nonce", nullptr}}, "wrong_nonce"},
        {"nobody", {{"sub", ""}}, "no_subject"},
        {"a subject past 255 characters", {{"sub", std::string(256, 'x')}}, "no_subject"},
    };
    auto keys = provider.cache();
    for (const Case& c : cases) {
        nlohmann::json claims = validClaims();
        claims.merge_patch(c.change);
        EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(claims), keys, expectations())), c.code) << c.what;
    }
    // within the allowed clock difference (120 s) each of those times is still taken
    nlohmann::json edges = validClaims();
    edges.merge_patch({{"exp", kNow - 119}, {"iat", kNow + 119}, {"nbf", kNow + 119},
                       {"aud", {kClient}}, {"azp", kClient}});
    EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(edges), keys, expectations())), "");
}

TEST_F(OidcIdTokens, OnlyThePublishedKeysAsymmetricSignatureIsTrusted)
{
    auto keys = provider.cache();
    const std::string token = sRsa->sign(validClaims());
    const std::size_t firstDot = token.find('.'), secondDot = token.find('.', firstDot + 1);
    const std::string header = token.substr(0, firstDot), signature = token.substr(secondDot + 1);

    // claims changed after signing
    nlohmann::json changed = validClaims();
    changed["sub"] = "1";
    EXPECT_EQ(refusal(verifyIdToken(header + "." + encodeBase64Url(changed.dump()) + "." + signature, keys,
                                    expectations())), "bad_signature");
    // "none", and HMAC keyed with what an attacker can read (the public key)
    for (const char* alg : {"none", "HS256"}) {
        const std::string h = encodeBase64Url(nlohmann::json{{"alg", alg}, {"kid", "rsa-1"}}.dump());
        EXPECT_EQ(refusal(verifyIdToken(h + "." + encodeBase64Url(validClaims().dump()) + "." + signature, keys,
                                        expectations())), "unsupported_algorithm") << alg;
    }
    // the RSA key's id on an EC signature, and an EC algorithm on the RSA key
    EXPECT_EQ(refusal(verifyIdToken(sEc->sign(validClaims(), {{"kid", "rsa-1"}}), keys, expectations())), "unknown_key");
    EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims(), {{"alg", "ES256"}}), keys, expectations())), "unknown_key");
    // a key of the same type that the provider does not publish, under a published key id
    const SigningKey stranger("rsa-1");
    EXPECT_EQ(refusal(verifyIdToken(stranger.sign(validClaims()), keys, expectations())), "bad_signature");
    // not a compact JWS
    for (const std::string& bad : {std::string("abc"), header + "." + signature, token + ".x", std::string("a.b.c"),
                                  std::string(kMaxIdTokenBytes + 1, 'a')})
        EXPECT_EQ(refusal(verifyIdToken(bad, keys, expectations())), "malformed") << bad.substr(0, 40);
    EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims(), {{"crit", {"exp"}}}), keys, expectations())), "malformed");
}

TEST_F(OidcIdTokens, ARotatedKeyIsFetchedAtOnceButUnknownKeysAtMostOncePerMinute)
{
    auto keys = provider.cache();
    const auto start = ProviderKeyCache::Clock::now();
    ASSERT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims()), keys, expectations(), start)), "");
    ASSERT_EQ(provider.fetches, 1);

    // the provider rotates: a new key beside the old one
    const SigningKey rotated("rsa-2");
    provider.published["keys"].push_back(rotated.jwk());
    EXPECT_EQ(refusal(verifyIdToken(rotated.sign(validClaims()), keys, expectations(), start + std::chrono::seconds(1))), "")
        << "a rotation right after the set's fetch";
    EXPECT_EQ(provider.fetches, 2);

    // made-up key ids: one more fetch, then none for a minute
    const auto later = start + std::chrono::seconds(200);
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims(), {{"kid", "made-up-" + std::to_string(i)}}), keys,
                                        expectations(), later + std::chrono::seconds(i))), "unknown_key");
    EXPECT_EQ(provider.fetches, 3);
    EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims(), {{"kid", "made-up"}}), keys, expectations(),
                                    later + std::chrono::seconds(61))), "unknown_key");
    EXPECT_EQ(provider.fetches, 4);

    // the old key withdrawn: after the set's hour its tokens are refused
    provider.published["keys"] = nlohmann::json::array({rotated.jwk()});
    EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims()), keys, expectations(), later + std::chrono::seconds(62))), "")
        << "within the hour the kept set still holds it";
    EXPECT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims()), keys, expectations(), start + std::chrono::hours(2))),
              "unknown_key");
}

TEST_F(OidcIdTokens, AProviderThatCannotBeReachedIsNamedAndTheKeptSetStillServes)
{
    provider.reachable = false;
    auto unreachable = provider.cache();
    const auto outcome = verifyIdToken(sRsa->sign(validClaims()), unreachable, expectations());
    ASSERT_EQ(refusal(outcome), "keys_unavailable");
    EXPECT_NE(std::get<IdTokenError>(outcome).message.find("connection refused"), std::string::npos);

    provider.reachable = true;
    auto keys = provider.cache();
    const auto start = ProviderKeyCache::Clock::now();
    ASSERT_EQ(refusal(verifyIdToken(sRsa->sign(validClaims()), keys, expectations(), start)), "");
    provider.reachable = false;
    EXPECT_EQ(refusal(verifyIdToken(sEc->sign(validClaims()), keys, expectations(), start + std::chrono::hours(2))), "")
        << "a failed refresh keeps the set fetched before";
}

TEST(OidcKeySets, KeysThatCannotSignTokensAreSkippedAndASetWithoutAnyIsRefused)
{
    const SigningKey rsa("sig"), small("small", "RSA", 1024), ec("ec", "EC");
    nlohmann::json encryption = rsa.jwk();
    encryption["use"] = "enc";
    encryption["kid"] = "enc";
    nlohmann::json otherCurve = ec.jwk();
    otherCurve["crv"] = "P-521";
    otherCurve["kid"] = "p521";
    nlohmann::json offCurve = ec.jwk();
    offCurve["kid"] = "off";
    offCurve["y"] = offCurve["x"];
    std::string error;
    const auto set = JsonWebKeySet::parse(
        {{"keys", {rsa.jwk(), small.jwk(), encryption, otherCurve, offCurve, ec.jwk(), 42, {{"kty", "oct"}, {"k", "AAAA"}}}}},
        error);
    ASSERT_TRUE(set) << error;
    EXPECT_EQ(set->size(), 2U);
    EXPECT_NE(set->find("sig", "RS256"), nullptr);
    EXPECT_EQ(set->find("sig", "RS512"), nullptr) << "the key's own alg binds it";
    EXPECT_NE(set->find("ec", "ES256"), nullptr);
    EXPECT_EQ(set->find("small", "RS256"), nullptr);
    EXPECT_EQ(set->find("", "RS256"), set->find("sig", "RS256")) << "without a kid, the only key of the type";

    EXPECT_FALSE(JsonWebKeySet::parse({{"keys", {small.jwk(), encryption}}}, error));
    EXPECT_NE(error.find("no RSA"), std::string::npos);
    EXPECT_FALSE(JsonWebKeySet::parse(nlohmann::json::array(), error));
    EXPECT_NE(error.find("not a JSON Web Key Set"), std::string::npos);
}

TEST(OidcKeySets, Base64UrlRoundTripsAndRefusesPaddingAndOtherAlphabets)
{
    const std::string bytes("\xfb\xff\x00\x01 tlmhub", 11);
    EXPECT_EQ(encodeBase64Url(bytes), "-_8AASB0bG1odWI");
    EXPECT_EQ(decodeBase64Url("-_8AASB0bG1odWI"), bytes);
    EXPECT_FALSE(decodeBase64Url("+/8AASB0bG1odWI"));
    EXPECT_FALSE(decodeBase64Url("YQ=="));
    EXPECT_EQ(decodeBase64Url(""), std::string{});
}
