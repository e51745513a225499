#include "server/auth/SignInHandOver.h"

#include "server/auth/oidc/AuthorizationRequest.h"

namespace tlmhub::server {

std::string handOverSignIn(SignInStore& signIns, std::int64_t userId, std::int64_t nowUnix)
{
    const std::string key = newSignInSecrets().state;
    signIns.add({key, "", "", "", "", nowUnix, userId});   // collected by key alone: the app's POST
    return key;
}

std::optional<std::int64_t> collectSignIn(SignInStore& signIns, const std::string& key, std::int64_t nowUnix)
{
    const auto handed = signIns.take(key, nowUnix - kHandOverSeconds);
    if (!handed || handed->userId == 0) return std::nullopt;
    return handed->userId;
}

} // namespace tlmhub::server
