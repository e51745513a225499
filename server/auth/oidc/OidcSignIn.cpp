#include "server/auth/oidc/OidcSignIn.h"

#include "server/auth/SignInHandOver.h"

#include "server/auth/DirectorySignIn.h"
#include "server/auth/SecretFile.h"
#include "server/auth/Sodium.h"
#include "server/auth/oidc/JsonMembers.h"

#include <openssl/crypto.h>

namespace tlmhub::server {

namespace {

// The display name's letters and digits, lower case, other runs as '-': "TU Graz" -> "tu-graz".
std::string addressName(const std::string& displayName)
{
    std::string name;
    for (const char c : displayName) {
        const bool alnum = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
        const bool upper = c >= 'A' && c <= 'Z';
        if (alnum || upper) name += upper ? static_cast<char>(c - 'A' + 'a') : c;
        else if (!name.empty() && name.back() != '-') name += '-';
    }
    while (!name.empty() && name.back() == '-') name.pop_back();
    return name.empty() ? "provider" : name.substr(0, 40);
}

// Whether the claim (a string or an array of strings) holds `value`.
bool claimHolds(const nlohmann::json& claims, const std::string& claim, const std::string& value)
{
    const auto it = claims.find(claim);
    if (it == claims.end()) return false;
    if (it->is_string()) return it->get<std::string>() == value;
    if (!it->is_array()) return false;
    for (const nlohmann::json& item : *it)
        if (item.is_string() && item.get<std::string>() == value) return true;
    return false;
}

// A name for a new account: the provider's user name, else the person's name, else the
// e-mail address's part before the @ (only for the name: accounts are never matched by it).
std::string wantedName(const nlohmann::json& claims)
{
    for (const char* claim : {"preferred_username", "name"})
        if (const std::string value = stringMember(claims, claim); !value.empty()) return value;
    const std::string email = stringMember(claims, "email");
    return email.empty() ? "user" : email.substr(0, email.find('@'));
}

} // namespace

OidcSignIn::OidcSignIn(const ServerOptions& options, UserStore& users, SignInStore& signIns)
    : mUsers(users), mSignIns(signIns), mPublicUrl(options.publicUrl), mCreateAccounts(options.oidcCreateAccounts),
      mHttp(options.oidcCaFile)
{
    for (const ServerOptions::OidcProviderOption& option : options.oidcProviders) {
        std::string name = addressName(option.displayName);
        for (int n = 2; find(name); ++n) name = addressName(option.displayName) + "-" + std::to_string(n);
        OidcProviderSettings settings{name, option.displayName, option.issuer, option.clientId,
                                      readSecretFile(option.clientSecretFile, "OpenID client secret file")};
        if (settings.clientSecret.empty())
            throw std::runtime_error("OpenID client secret file " + option.clientSecretFile + " is empty");
        mProviders.push_back({name, option, std::make_unique<OidcProvider>(std::move(settings), mHttp)});
    }
}

nlohmann::json OidcSignIn::providersJson() const
{
    nlohmann::json list = nlohmann::json::array();
    for (const Provider& provider : mProviders)
        list.push_back({{"name", provider.name}, {"display_name", provider.option.displayName}});
    return list;
}

OidcSignIn::Provider* OidcSignIn::find(const std::string& name)
{
    for (Provider& provider : mProviders)
        if (provider.name == name) return &provider;
    return nullptr;
}

std::string OidcSignIn::redirectUri(const Provider& provider) const
{
    return mPublicUrl + "/api/v1/auth/oidc/" + provider.name + "/callback";
}

OidcOutcome OidcSignIn::start(const std::string& name, const std::string& clientAddress, std::int64_t nowUnix)
{
    Provider* provider = find(name);
    if (!provider) return OidcOutcome::refused("not_found", "no such sign-in provider");
    if (!mStartsPerAddress.allowed(clientAddress))
        return OidcOutcome::refused("busy", "too many sign-ins started from " + clientAddress);
    mStartsPerAddress.recordFailure(clientAddress);   // counts the start
    // Unanswered starts are purged after their wait; past the cap the next starts wait too.
    if (mSignIns.purge(nowUnix - kSignInSeconds) >= kMaxPendingSignIns)
        return OidcOutcome::refused("busy", "10,000 sign-ins are under way");
    const SignInSecrets secrets = newSignInSecrets();
    std::string error;
    const auto location = provider->client->authorizationUrl(secrets, redirectUri(*provider), error);
    if (!location) return OidcOutcome::refused("provider_unavailable", provider->option.issuer + ": " + error);
    const std::string browserKey = newSignInSecrets().state;
    mSignIns.add({secrets.state, provider->name, secrets.nonce, secrets.codeVerifier, browserKey, nowUnix, 0});
    return OidcOutcome::sendTo(*location, browserKey);
}

OidcOutcome OidcSignIn::finish(const std::string& name, const std::string& code, const std::string& state,
                               const std::string& iss, const std::string& providerError,
                               const std::string& browserKey, std::int64_t nowUnix)
{
    // Taken whatever comes next: an answer is used once.
    const auto attempt = state.empty() ? std::nullopt : mSignIns.take(state, nowUnix - kSignInSeconds);
    Provider* provider = find(name);
    if (!provider || !attempt || attempt->provider != provider->name || attempt->userId != 0)
        return OidcOutcome::refused("sign_in_failed", "this sign-in has expired or was used already; start again");
    // Another browser's answer: someone signed in at the provider and sent the answer on (a
    // login CSRF would sign this browser in to their account).
    if (browserKey.size() != attempt->browserKey.size() ||
        CRYPTO_memcmp(browserKey.data(), attempt->browserKey.data(), browserKey.size()) != 0)
        return OidcOutcome::refused("sign_in_failed", "the answer came to another browser than the sign-in's");
    if (!providerError.empty())
        return OidcOutcome::refused("sign_in_failed", "the provider answered " + providerError.substr(0, 60));
    // RFC 9207: an answer naming another issuer came from another provider (a mix-up).
    if (!iss.empty() && iss != provider->option.issuer)
        return OidcOutcome::refused("sign_in_failed", "the answer came from another provider");
    const auto outcome = provider->client->finish(code, attempt->codeVerifier, attempt->nonce, redirectUri(*provider),
                                                  nowUnix);
    if (const auto* refused = std::get_if<IdTokenError>(&outcome))
        return OidcOutcome::refused("sign_in_failed", refused->code + ": " + refused->message);
    return account(*provider, std::get<IdToken>(outcome));
}

OidcOutcome OidcSignIn::account(const Provider& provider, const IdToken& token)
{
    std::string role = kRoleUser;
    for (const auto& [mapped, value] : provider.option.roles)
        if (claimHolds(token.claims, provider.option.roleClaim, value) && roleRank(mapped) > roleRank(role)) role = mapped;
    const std::string identityProvider = "oidc " + provider.option.issuer;
    std::optional<User> user = mUsers.findByIdentity(identityProvider, token.subject);
    if (!user && !mCreateAccounts)
        return OidcOutcome::refused("no_account", "no account is made on first sign-in (--oidc-create-accounts off)");
    if (!user)
        return OidcOutcome::signedIn(
            mUsers.insertLinked(identityProvider, token.subject, accountNameFor(wantedName(token.claims)), role));
    // The claim decides the role when any roles are mapped (the last administrator keeps theirs).
    if (!provider.option.roles.empty() && user->role != role) {
        User updated;
        UserChange change;
        change.role = role;
        if (mUsers.change(user->id, change, updated) == UserChangeOutcome::Changed) user = updated;
    }
    return OidcOutcome::signedIn(*user);
}

std::string OidcSignIn::handOver(const User& user, std::int64_t nowUnix)
{
    return handOverSignIn(mSignIns, user.id, nowUnix);
}

} // namespace tlmhub::server
