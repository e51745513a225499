#include "server/auth/Accounts.h"

#include "server/auth/PasswordHasher.h"

namespace tlmhub::server {

namespace {

bool isUsernameChar(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
           c == '_' || c == '.' || c == '-';
}

// Verified against when the user does not exist, so a miss costs as much as a wrong password.
const std::string& decoyHash()
{
    static const std::string hash = hashPassword("tlmhub decoy password");
    return hash;
}

} // namespace

bool isValidUsername(const std::string& username)
{
    if (username.empty() || username.size() > 64) return false;
    for (char c : username)
        if (!isUsernameChar(c)) return false;
    return true;
}

Accounts::Accounts(UserStore& store) : mStore(store) {}

std::optional<User> Accounts::create(const std::string& username, const std::string& password,
                                     const std::string& role, std::string& error)
{
    if (!isValidUsername(username)) { error = kBadUsername; return std::nullopt; }
    if (!isValidRole(role)) { error = kBadRole; return std::nullopt; }
    if (password.size() < kMinPasswordLength) { error = kShortPassword; return std::nullopt; }
    // Checked before hashing too, so a taken name is refused without 0.1 s of work; the store
    // checks again, for a concurrent create of the same name.
    if (mStore.credentials(username)) { error = kUsernameTaken; return std::nullopt; }
    auto user = mStore.insert(username, hashPassword(password), role);
    if (!user) error = kUsernameTaken;
    return user;
}

std::optional<User> Accounts::authenticate(const std::string& username, const std::string& password)
{
    const std::optional<Credentials> found = mStore.credentials(username);
    if (!found || !found->passwordHash) {
        verifyPassword(decoyHash(), password);
        return std::nullopt;
    }
    if (!verifyPassword(*found->passwordHash, password)) return std::nullopt;
    return mStore.find(found->id);
}

bool Accounts::changePassword(std::int64_t id, const std::string& oldPw, const std::string& newPw,
                              std::string& error)
{
    const std::optional<Credentials> found = mStore.credentials(id);
    if (!found) { error = kNoSuchUser; return false; }
    if (!found->passwordHash || !verifyPassword(*found->passwordHash, oldPw)) { error = kWrongPassword; return false; }
    if (newPw.size() < kMinPasswordLength) { error = kShortPassword; return false; }
    if (!mStore.setPasswordHash(id, hashPassword(newPw))) { error = kNoSuchUser; return false; }
    return true;
}

std::optional<User> Accounts::update(std::int64_t id, const std::optional<std::string>& role,
                                     std::optional<bool> disabled, std::string& error)
{
    if (role && !isValidRole(*role)) { error = kBadRole; return std::nullopt; }
    User updated;
    switch (mStore.change(id, UserChange{role, disabled}, updated)) {
    case UserChangeOutcome::Changed: return updated;
    case UserChangeOutcome::NoSuchUser: error = kNoSuchUser; return std::nullopt;
    case UserChangeOutcome::LastAdmin: error = kLastAdmin; return std::nullopt;
    }
    return std::nullopt;
}

} // namespace tlmhub::server
