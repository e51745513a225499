#pragma once
// Signing in through the OpenID providers the administrator configured (docs/sign-in.md): the
// start sends the browser to the provider with a sign-in's secrets kept in the database
// (SignInStore), the provider's answer is taken once and checked (OidcProvider), and the
// person gets the account linked to the provider's issuer and their `sub` (made on first
// sign-in unless turned off; never a local account matched by name or e-mail), with the
// role the configured claim gives. The login then goes to the browser app by a one-time
// hand-over key, traded once for a login, so no token appears in an address.
#include "server/app/ServerOptions.h"
#include "server/auth/LoginRateLimiter.h"
#include "server/auth/User.h"
#include "server/auth/oidc/OidcProvider.h"
#include "server/auth/oidc/ProviderHttp.h"
#include "server/store/SignInStore.h"
#include "server/store/UserStore.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct OidcOutcome {
    std::optional<User> user;   // signed in
    std::string location;       // start: where the browser goes ...
    std::string browserKey;     // ... with this value in its sign-in cookie
    // else why not: the code (not_found, provider_unavailable, busy, sign_in_failed, no_account)
    // for the person, the message with the details for the server's log
    std::string code, message;

    static OidcOutcome signedIn(User user) { return {std::move(user), {}, {}, {}, {}}; }
    static OidcOutcome sendTo(std::string location, std::string browserKey)
    {
        return {std::nullopt, std::move(location), std::move(browserKey), {}, {}};
    }
    static OidcOutcome refused(std::string code, std::string message)
    {
        return {std::nullopt, {}, {}, std::move(code), std::move(message)};
    }
};

class OidcSignIn {
public:
    // Reads each provider's client secret file (throws naming it when it cannot).
    OidcSignIn(const ServerOptions& options, UserStore& users, SignInStore& signIns);

    // [{name, display_name}] in the order configured.
    nlohmann::json providersJson() const;
    // The provider's authorization address for a new sign-in from `clientAddress` (busy past
    // kMaxStartsPerAddress in kStartWindow, so one address cannot use up the pending sign-ins).
    OidcOutcome start(const std::string& name, const std::string& clientAddress, std::int64_t nowUnix);
    // The provider's answer (the callback's query: code, state, iss, error) in the browser
    // whose sign-in cookie holds `browserKey`: the account.
    OidcOutcome finish(const std::string& name, const std::string& code, const std::string& state,
                       const std::string& iss, const std::string& providerError, const std::string& browserKey,
                       std::int64_t nowUnix);
    // A one-time key for the app to collect the sign-in of `user` with (SignInHandOver.h).
    std::string handOver(const User& user, std::int64_t nowUnix);

    const std::string& publicUrl() const { return mPublicUrl; }

    static constexpr std::int64_t kSignInSeconds = 600;   // from the start to the provider's answer
    static constexpr std::size_t kMaxPendingSignIns = 10'000;
    // A class of 40 behind one address, each starting a few times, stays far below.
    static constexpr int kMaxStartsPerAddress = 300;
    static constexpr std::chrono::minutes kStartWindow{10};

private:
    struct Provider {
        std::string name;   // in addresses: the display name's letters and digits
        ServerOptions::OidcProviderOption option;
        std::unique_ptr<OidcProvider> client;
    };
    Provider* find(const std::string& name);
    std::string redirectUri(const Provider& provider) const;
    // The account of the token's person (made or found), with the role the claims give.
    OidcOutcome account(const Provider& provider, const IdToken& token);

    UserStore& mUsers;
    SignInStore& mSignIns;
    const std::string mPublicUrl;
    const bool mCreateAccounts;
    ProviderHttp mHttp;
    std::vector<Provider> mProviders;
    LoginRateLimiter mStartsPerAddress{kMaxStartsPerAddress, kStartWindow};
};

} // namespace tlmhub::server
