#include "server/store/UserStore.h"

#include "server/auth/AccessPolicy.h"

#include <algorithm>

namespace tlmhub::server {

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
