#pragma once
// First-start setup: the admin account and the example models.
#include "server/store/ModelStore.h"
#include "server/auth/Accounts.h"
#include "server/store/MetaStore.h"
#include "server/store/ModelStore.h"

#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

inline constexpr const char* kAdminUsername = "admin";

// Creates user "admin" if it does not exist. The password is `envPassword` (the value of
// TLMHUB_ADMIN_PASSWORD, may be null) when set and non-empty, else 16 random characters.
// Returns the password only when it was generated here, so main can print it once; nullopt
// when the admin already existed or the operator chose the password.
// Throws std::runtime_error when the given password is refused (e.g. shorter than 8).
std::optional<std::string> ensureAdmin(Accounts& users, const char* envPassword);

// Stores every *.hmf of each directory (sorted by file name) as an example owned by the
// admin, named after the file stem. Each file name is seeded once ever (meta key
// "seeded:<file name>"), so an example the admin deleted stays deleted after a restart.
// Files that do not load are skipped (and retried next start). Appends one line per file or
// problem to `log`; returns the number of examples added.
int seedExamples(ModelStore& models, MetaStore& meta, Accounts& users,
                 const std::vector<std::string>& dirs, std::string& log);

} // namespace tlmhub::server
