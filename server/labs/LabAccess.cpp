#include "server/labs/LabAccess.h"

#include "server/auth/AccessPolicy.h"

namespace tlmhub::server {

std::optional<ClassView> classFor(LabStore& labs, const User& who, std::int64_t classId)
{
    auto info = labs.classInfo(classId);
    if (!info) return std::nullopt;
    if (isAdministrator(who)) return ClassView{std::move(*info), kClassTeacher};
    auto role = labs.memberRole(classId, who.id);
    if (!role) return std::nullopt;
    return ClassView{std::move(*info), std::move(*role)};
}

std::optional<AssignmentView> assignmentFor(LabStore& labs, const User& who, std::int64_t assignmentId,
                                            std::int64_t now)
{
    auto assignment = labs.assignment(assignmentId);
    if (!assignment) return std::nullopt;
    auto view = classFor(labs, who, assignment->classId);
    if (!view) return std::nullopt;
    if (view->isStudent() && assignment->opensAt > now) return std::nullopt;
    return AssignmentView{std::move(*assignment), std::move(*view)};
}

CopyAccess copyAccess(LabStore& labs, const User& who, std::int64_t modelId)
{
    const auto copy = labs.copyByModel(modelId);
    if (!copy) return {};
    const auto assignment = labs.assignment(copy->assignmentId);
    if (!assignment) return {CopyAccess::Kind::None, std::nullopt};
    const auto theClass = labs.classInfo(assignment->classId);
    if (isAdministrator(who)) return {CopyAccess::Kind::Read, std::nullopt};
    if (who.id == copy->studentId) {
        // A student removed from the class loses the copy with the class.
        if (labs.memberRole(assignment->classId, who.id) != std::optional<std::string>(kClassStudent))
            return {CopyAccess::Kind::None, std::nullopt};
        if (!theClass || theClass->archived) return {CopyAccess::Kind::Read, std::nullopt};
        CopyAccess access{CopyAccess::Kind::Write, std::nullopt};
        if (assignment->editMode == "parameters") {
            std::string error;
            access.lock = ParameterLock::parse(nlohmann::json::parse(assignment->parameters, nullptr, false), error);
            if (!access.lock) access.lock = ParameterLock();   // unreadable list: nothing may change
        }
        return access;
    }
    if (labs.supervisesCopy(who.id, modelId)) return {CopyAccess::Kind::Read, std::nullopt};
    return {CopyAccess::Kind::None, std::nullopt};
}

} // namespace tlmhub::server
