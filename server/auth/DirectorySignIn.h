#pragma once
// Signing in with a directory's user name and password (LDAP, docs/sign-in.md): the person
// the directory vouches for gets the account linked to them (UserStore's identities), made
// on their first sign-in; its role follows the directory's groups when any are mapped. A
// local account of the same name stays someone else's.
#include "server/auth/LdapDirectory.h"
#include "server/auth/User.h"
#include "server/store/UserStore.h"

#include <optional>
#include <string>

namespace tlmhub::server {

struct DirectorySignInResult {
    enum class Outcome { SignedIn, WrongCredentials, Unavailable, NoAccount } outcome = Outcome::WrongCredentials;
    std::optional<User> user;
    std::string message;   // Unavailable: why (for the log and the caller); NoAccount: what to do
};

class DirectorySignIn {
public:
    // `createAccounts` off: only people an administrator linked before sign in (none are made).
    DirectorySignIn(const LdapDirectory& directory, UserStore& users, bool createAccounts);

    DirectorySignInResult signIn(const std::string& username, const std::string& password);
    // "ldap ldaps://ldap.uni.edu": the identities' provider.
    const std::string& provider() const { return mProvider; }

private:
    const LdapDirectory& mDirectory;
    UserStore& mUsers;
    bool mCreateAccounts;
    std::string mProvider;
};

// A directory's user name as one of ours: characters a name may not have become '_', cut to
// 60 (room for "-2" and up when it is taken).
std::string accountNameFor(const std::string& directoryName);

} // namespace tlmhub::server
