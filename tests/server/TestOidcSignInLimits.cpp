// Sign-in starts are bounded (issue 43 item 1): anyone may start one, and each keeps a row for
// 10 minutes, so one address may start at most 300 in that time; another address is not
// held up. The provider here cannot be reached, which the start says without asking it again
// for a minute.
#include "ServerHarness.h"

#include "server/auth/oidc/OidcSignIn.h"
#include "server/store/Storage.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace tlmhub::server;

TEST(OidcSignInLimits, OneAddressStartsAtMost300SignInsInTenMinutesAndOthersAreNotHeldUp)
{
    const auto dir = tlmhub::test::freshTempDir("oidc-limits");
    const auto secret = dir / "client-secret";
    std::ofstream(secret) << "secret\n";
    std::filesystem::permissions(secret, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    ServerOptions options;
    options.publicUrl = "https://tlmhub.example.edu";
    ServerOptions::OidcProviderOption& provider = options.oidcProviders.emplace_back();
    provider.issuer = "https://127.0.0.1:" + std::to_string(tlmhub::test::freeLoopbackPort());
    provider.clientId = "tlmhub";
    provider.clientSecretFile = secret.string();
    provider.displayName = "University";
    const auto storage = openStorage({.database = ":memory:"});
    OidcSignIn signIn(options, storage->users(), storage->signIns());
    EXPECT_EQ(signIn.providersJson(), nlohmann::json::parse(R"([{"name": "university", "display_name": "University"}])"));

    const std::int64_t now = 1'800'000'000;
    for (int i = 0; i < OidcSignIn::kMaxStartsPerAddress; ++i)
        ASSERT_EQ(signIn.start("university", "10.0.0.1", now).code, "provider_unavailable") << i;
    const OidcOutcome held = signIn.start("university", "10.0.0.1", now);
    EXPECT_EQ(held.code, "busy");
    EXPECT_NE(held.message.find("10.0.0.1"), std::string::npos) << held.message;
    EXPECT_EQ(signIn.start("university", "10.0.0.2", now).code, "provider_unavailable") << "another address";
    EXPECT_EQ(signIn.start("nowhere", "10.0.0.3", now).code, "not_found");
    std::filesystem::remove_all(dir);
}
