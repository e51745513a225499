#pragma once
// What the lab routes (ClassRoutes, AssignmentRoutes, HandInRoutes) share: the class or
// assignment of the path as the caller may see it, and the lab's refusals.
#include "server/api/ApiSupport.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"

#include <optional>

namespace tlmhub::server {

// The class {id} of the path, when the caller is a member (else nullopt: answer 404).
std::optional<ClassView> visibleClass(Services& s, const Call& call);
// The assignment {id} of the path, when the caller may see it.
std::optional<AssignmentView> visibleAssignment(Services& s, const Call& call);

Response labNotFound(const std::string& what);
Response labArchived();
// The HTTP status of a lab refusal by its code.
Response labErrorResponse(const LabError& error);
// An assignment's checks; `everything` false (a student): hand-in checks without their definition.
nlohmann::json checksJson(const std::vector<AssignmentCheck>& checks, bool everything);

} // namespace tlmhub::server
