#include "server/store/UserStore.h"

#include "server/auth/AccessPolicy.h"

#include <algorithm>

namespace tlmhub::server {

std::string suffixedUsername(const std::string& username, int n)
{
    const std::string suffix = "-" + std::to_string(n);
    constexpr std::size_t kMaxLength = 64;
    return username.substr(0, kMaxLength - std::min(kMaxLength, suffix.size())) + suffix;
}

UserChangeOutcome applyUserChange(const std::vector<User>& all, std::int64_t id, const UserChange& change,
                                  User& updated)
{
    const auto found = std::ranges::find(all, id, &User::id);
    if (found == all.end()) return UserChangeOutcome::NoSuchUser;
    User user = *found;
    if (change.role) user.role = *change.role;
    if (change.disabled) user.disabled = *change.disabled;
    const bool anotherAdministers = std::ranges::any_of(
        all, [&](const User& other) { return other.id != id && administersServer(other); });
    if (administersServer(*found) && !administersServer(user) && !anotherAdministers)
        return UserChangeOutcome::LastAdmin;
    updated = user;
    return UserChangeOutcome::Changed;
}

} // namespace tlmhub::server
