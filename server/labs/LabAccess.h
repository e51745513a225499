#pragma once
// Who may see and change what in a lab (docs/labs.md, "Who may do what"): a member's role in
// a class, and what a user may do with a student's copy. The one place these rules live;
// routes, the model and job paths and the WebSocket ask here.
#include "server/auth/User.h"
#include "server/labs/ParameterLock.h"
#include "server/store/LabStore.h"

#include <optional>
#include <string>

namespace tlmhub::server {

// A class as `who` may see it, with their role in it (an administrator acts as its teacher).
struct ClassView {
    ClassInfo info;
    std::string role;
    bool isTeacher() const { return role == kClassTeacher; }
    bool isStaff() const { return role == kClassTeacher || role == kClassAssistant; }
    bool isStudent() const { return role == kClassStudent; }
};

// Nullopt when `who` is not a member (or the class does not exist): such a class answers 404.
std::optional<ClassView> classFor(LabStore& labs, const User& who, std::int64_t classId);
// The assignment and its class as `who` may see them: staff see every assignment; students
// only those already open (opens_at passed).
struct AssignmentView {
    AssignmentInfo assignment;
    ClassView classView;
};
std::optional<AssignmentView> assignmentFor(LabStore& labs, const User& who, std::int64_t assignmentId,
                                            std::int64_t now);

// What `who` may do with model `modelId` as a lab copy.
struct CopyAccess {
    enum class Kind {
        NotACopy,   // the ordinary rules apply (AccessPolicy)
        None,       // a copy `who` may not see (404)
        Read,       // staff of its class, or its student in an archived class
        Write,      // its student (within the lock, if any)
    } kind = Kind::NotACopy;
    std::optional<ParameterLock> lock;   // Write with edit mode "parameters"
};
CopyAccess copyAccess(LabStore& labs, const User& who, std::int64_t modelId);

} // namespace tlmhub::server
