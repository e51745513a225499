#pragma once
// Who may see and change a model or job. The one place these rules live; stores and
// handlers ask here instead of comparing roles themselves.
//   admin:   everything
//   owner:   own objects
//   example: readable by everyone, changed by admin only
//   lab supervision (a teacher or assistant reading students' copies and their runs) is
//   decided by class membership: server/labs/LabAccess
//   jobs:    cancelled, stopped and deleted by their owner or an admin; re-run by the owner
//   accounts and server stats: admin only
//   the last enabled admin account may be neither demoted nor disabled
#include "server/auth/User.h"

#include <cstdint>
#include <string>

namespace tlmhub::server {

bool canRead(const User& who, std::int64_t ownerId, bool isExample);
bool canWrite(const User& who, std::int64_t ownerId, bool isExample);
bool canControlJob(const User& who, std::int64_t ownerId);
bool canRerunJob(const User& who, std::int64_t ownerId);
bool isAdministrator(const User& who);
// Whether `account` (as it is, or would be after a change) administers the server: the
// user store refuses a change that would leave no such account.
bool administersServer(const User& account);

} // namespace tlmhub::server
