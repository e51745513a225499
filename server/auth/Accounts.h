#pragma once
// Accounts: creating, logging in, changing passwords and roles, with the rules of each (valid
// names, password length, argon2id hashes, a last administrator). What is stored goes through
// UserStore; hashing (about 0.1 s) happens before any database work.
#include "server/auth/User.h"
#include "server/store/UserStore.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

// Error texts of create()/changePassword(), fixed so callers can map them to API codes
// (kUsernameTaken -> conflict, the rest -> bad_request / unauthorized).
inline constexpr const char* kUsernameTaken = "username is already taken";
inline constexpr const char* kBadUsername =
    "username must be 1-64 characters of A-Z, a-z, 0-9, '_', '.', '-'";
inline constexpr const char* kBadRole = "role must be admin, teacher or user";
inline constexpr const char* kShortPassword = "password must be at least 8 characters";
inline constexpr const char* kWrongPassword = "old password is wrong";
inline constexpr const char* kNoSuchUser = "no such user";
inline constexpr const char* kLastAdmin = "the last enabled administrator cannot be disabled or lose the role";

inline constexpr std::size_t kMinPasswordLength = 8;

bool isValidUsername(const std::string& username);

class Accounts {
public:
    explicit Accounts(UserStore& store);

    // Names are unique regardless of case ("ALICE" is taken when "alice" exists).
    std::optional<User> create(const std::string& username, const std::string& password,
                               const std::string& role, std::string& error);
    // The user when the password matches (also a disabled one: the caller refuses it, after
    // the password proved who asks); nullopt for unknown user or wrong password (both take
    // the time of one hash, so timing does not reveal which names exist). The name matches
    // exactly, or else regardless of case when that finds one account.
    std::optional<User> authenticate(const std::string& username, const std::string& password);
    std::optional<User> find(std::int64_t id) { return mStore.find(id); }
    std::optional<User> findByName(const std::string& username) { return mStore.findByName(username); }
    std::vector<User> list() { return mStore.list(); }   // by id
    std::size_t count() { return mStore.count(); }
    bool changePassword(std::int64_t id, const std::string& oldPw, const std::string& newPw,
                        std::string& error);
    // An administrator's change of role and/or enabled state; the updated user, or nullopt
    // with `error` (kNoSuchUser, kBadRole, kLastAdmin).
    std::optional<User> update(std::int64_t id, const std::optional<std::string>& role,
                               std::optional<bool> disabled, std::string& error);
    // Existing names that differ only in case (made before names were compared that way),
    // one "alice, ALICE" line per group; they keep working, the server reports them at start.
    std::vector<std::string> namesDifferingOnlyInCase() { return mStore.namesDifferingOnlyInCase(); }
    // The account's own settings as stored JSON text (UserStore::preferences).
    std::optional<std::string> preferences(std::int64_t id) { return mStore.preferences(id); }
    bool setPreferences(std::int64_t id, const std::string& json) { return mStore.setPreferences(id, json); }

private:
    UserStore& mStore;
};

} // namespace tlmhub::server
