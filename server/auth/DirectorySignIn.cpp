#include "server/auth/DirectorySignIn.h"

#include <algorithm>

namespace tlmhub::server {

std::string accountNameFor(const std::string& directoryName)
{
    std::string name;
    for (const char c : directoryName.substr(0, 60)) {
        const bool allowed = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'
                             || c == '.' || c == '-';
        name += allowed ? c : '_';
    }
    return name.empty() ? "user" : name;
}

DirectorySignIn::DirectorySignIn(const LdapDirectory& directory, UserStore& users, bool createAccounts)
    : mDirectory(directory), mUsers(users), mCreateAccounts(createAccounts), mProvider("ldap " + directory.settings().url)
{
}

DirectorySignInResult DirectorySignIn::signIn(const std::string& username, const std::string& password)
{
    using Outcome = DirectorySignInResult::Outcome;
    const LdapSignIn found = mDirectory.signIn(username, password);
    if (found.outcome == LdapSignIn::Outcome::WrongCredentials) return {};
    if (found.outcome == LdapSignIn::Outcome::Unavailable)
        return {.outcome = Outcome::Unavailable, .user = std::nullopt, .message = found.message};

    const auto& groups = mDirectory.settings().roleGroups;
    std::string role = kRoleUser;
    for (const LdapSettings::RoleGroup& group : groups)
        if (std::ranges::find(found.groups, group.groupDn) != found.groups.end() && roleRank(group.role) > roleRank(role))
            role = group.role;

    std::optional<User> user = mUsers.findByIdentity(mProvider, found.subject);
    if (!user && !mCreateAccounts)
        return {.outcome = Outcome::NoAccount,
                .user = std::nullopt,
                .message = "the directory knows you, but this server makes no accounts on first sign-in; ask an administrator"};
    if (!user) return {.outcome = Outcome::SignedIn, .user = mUsers.insertLinked(mProvider, found.subject, accountNameFor(username), role), .message = {}};
    // The directory's groups decide the role when any are mapped (the last administrator keeps theirs).
    if (!groups.empty() && user->role != role) {
        User updated;
        UserChange change;
        change.role = role;
        if (mUsers.change(user->id, change, updated) == UserChangeOutcome::Changed) user = updated;
    }
    return {.outcome = Outcome::SignedIn, .user = user, .message = {}};
}

} // namespace tlmhub::server
