#pragma once
// Sign-ins through a provider between their start and the provider's answer (table
// sign_in_attempts; OpenID Connect now, LTI's third-party-initiated login later): what the
// answer is checked with, kept in the database so that any API node takes the answer, and
// taken once, so a replayed answer finds nothing (its state, and with it its nonce, are
// used). Once the person is signed in, a second row hands the sign-in to the browser app: a new
// random key that the app trades once for a login, so no token appears in an address or is
// stored here. Rows that are never taken are purged once older than the wait allowed.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace tlmhub::server {

struct SignInAttempt {
    std::string state;          // the key: the random value the provider hands back
    std::string provider;       // the configured provider's name
    std::string nonce, codeVerifier;
    // The random value of the cookie the start gave the browser: the answer is taken only from
    // that browser (no login CSRF: someone else's answer pushed into this browser)
    std::string browserKey;
    std::int64_t createdAt = 0; // unix s
    std::int64_t userId = 0;    // a hand-over to the app: the account signed in (else 0)
};

class SignInStore {
public:
    virtual ~SignInStore() = default;

    // Stores a new attempt (its state is new: 32 random bytes).
    virtual void add(const SignInAttempt& attempt) = 0;
    // The attempt with `state`, removed in the same step, so of two takes racing on any nodes
    // one gets it; nullopt when there is none or it was made before `notBeforeUnix`.
    virtual std::optional<SignInAttempt> take(const std::string& state, std::int64_t notBeforeUnix) = 0;
    // Removes the attempts made before `notBeforeUnix`; then how many are left (what a start
    // is limited by, so unanswered starts cannot fill the database).
    virtual std::size_t purge(std::int64_t notBeforeUnix) = 0;
};

} // namespace tlmhub::server
