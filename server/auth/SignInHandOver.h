#pragma once
// The end of a sign-in that happened away from the app (a provider's answer, a learning
// platform's launch): the browser is sent to the app with a new random key in the address's
// fragment, and the app trades that key once, within kHandOverSeconds, for a login (POST
// /api/v1/auth/oidc/collect), so no token appears in an address or a log. The key is a row of
// SignInStore with the account in it; any API node takes it.
#include "server/store/SignInStore.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tlmhub::server {

inline constexpr std::int64_t kHandOverSeconds = 60;

// A one-time key for the app to collect the sign-in of `userId` with.
std::string handOverSignIn(SignInStore& signIns, std::int64_t userId, std::int64_t nowUnix);
// The account of a hand-over key, once; nullopt when unknown, used or too old.
std::optional<std::int64_t> collectSignIn(SignInStore& signIns, const std::string& key, std::int64_t nowUnix);

} // namespace tlmhub::server
