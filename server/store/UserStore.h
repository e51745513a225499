#pragma once
// Accounts as stored (table users). Pure persistence: names, roles and password hashes are
// checked and made by server/auth/Accounts before they get here.
#include "server/auth/User.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct Credentials {
    std::int64_t id = 0;
    std::optional<std::string> passwordHash;   // none: the account cannot log in
};

struct UserChange {
    std::optional<std::string> role;
    std::optional<bool> disabled;
};

enum class UserChangeOutcome { Changed, NoSuchUser, LastAdmin };

// The rule of UserStore::change, for the back ends to apply to the accounts they read (and
// locked) in the change's transaction: `updated` gets account `id` of `all` with `change`
// applied, unless that would leave no enabled administrator (AccessPolicy's
// administersServer) or there is no such account.
UserChangeOutcome applyUserChange(const std::vector<User>& all, std::int64_t id, const UserChange& change,
                                  User& updated);

// `username` with "-n" appended, cut so the result stays within a name's 64 characters.
std::string suffixedUsername(const std::string& username, int n);

class UserStore {
public:
    virtual ~UserStore() = default;

    // The new account; nullopt when the name is taken, compared regardless of case ("ALICE"
    // when "alice" exists), also by a concurrent insert.
    virtual std::optional<User> insert(const std::string& username, const std::string& passwordHash,
                                       const std::string& role) = 0;
    // The account of exactly this name, else the one whose name matches regardless of case;
    // nullopt when none, or when two old accounts differ only in case.
    virtual std::optional<Credentials> credentials(const std::string& username) = 0;
    virtual std::optional<Credentials> credentials(std::int64_t id) = 0;
    // False when the account does not exist.
    virtual bool setPasswordHash(std::int64_t id, const std::string& passwordHash) = 0;
    virtual std::optional<User> find(std::int64_t id) = 0;
    virtual std::optional<User> findByName(const std::string& username) = 0;   // exact name
    virtual std::vector<User> list() = 0;   // by id
    virtual std::size_t count() = 0;
    // Applies `change` in one transaction, unless it would leave no enabled administrator
    // (AccessPolicy's administersServer) among all accounts; `updated` gets the account as it
    // is afterwards.
    virtual UserChangeOutcome change(std::int64_t id, const UserChange& change, User& updated) = 0;
    // The account's own settings (GET/PUT /preferences) as the JSON text stored, "{}" until
    // it sets some; nullopt when the account does not exist.
    virtual std::optional<std::string> preferences(std::int64_t id) = 0;
    // False when the account does not exist.
    virtual bool setPreferences(std::int64_t id, const std::string& json) = 0;
    // Existing names that differ only in case (made before names were compared that way),
    // one "alice, ALICE" line per group, names in id order.
    virtual std::vector<std::string> namesDifferingOnlyInCase() = 0;

    // Accounts of people who sign in through a directory or a provider (table identities):
    // `provider` names it ("ldap ldaps://ldap.example.org"), `subject` is who they are there
    // (an entry's DN). Never matched by name or e-mail: a directory's "admin" is not ours.
    //
    // The account linked to `subject` at `provider`; nullopt when none is.
    virtual std::optional<User> findByIdentity(const std::string& provider, const std::string& subject) = 0;
    // The account of `subject` at `provider`: the linked one, else a new one without a password
    // (it signs in there only), linked in the same transaction, named `username` or, when that
    // is taken, `username-2`, `username-3`, ... Two first sign-ins at once make one account.
    virtual User insertLinked(const std::string& provider, const std::string& subject, const std::string& username,
                              const std::string& role) = 0;
};

} // namespace tlmhub::server
