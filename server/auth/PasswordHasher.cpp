#include "server/auth/PasswordHasher.h"

#include "server/auth/Sodium.h"

#include <sodium.h>

#include <atomic>
#include <stdexcept>

namespace tlmhub::server {

namespace {
std::atomic<PasswordCost> gCost{PasswordCost::Interactive};
}

void setPasswordCost(PasswordCost cost)
{
    gCost = cost;
}

std::string hashPassword(const std::string& password)
{
    ensureSodium();
    const bool minimal = gCost == PasswordCost::Minimal;
    char out[crypto_pwhash_STRBYTES];
    if (crypto_pwhash_str_alg(out, password.data(), password.size(),
                              minimal ? crypto_pwhash_OPSLIMIT_MIN : crypto_pwhash_OPSLIMIT_INTERACTIVE,
                              minimal ? crypto_pwhash_MEMLIMIT_MIN : crypto_pwhash_MEMLIMIT_INTERACTIVE,
                              crypto_pwhash_ALG_ARGON2ID13) != 0)
        throw std::runtime_error("password hashing ran out of memory");
    return out;
}

bool verifyPassword(const std::string& hash, const std::string& password)
{
    ensureSodium();
    // crypto_pwhash_str_verify reads a NUL-terminated string of at most STRBYTES.
    if (hash.empty() || hash.size() >= crypto_pwhash_STRBYTES) return false;
    return crypto_pwhash_str_verify(hash.c_str(), password.data(), password.size()) == 0;
}

} // namespace tlmhub::server
