#include "server/labs/LiveLabAccess.h"

namespace tlmhub::server {

std::optional<LiveShareRefusal> liveShareRefusal(LabStore& labs, const User& who, std::int64_t classId)
{
    const auto view = classFor(labs, who, classId);
    if (!view) return LiveShareRefusal{"not_found", "no such class"};
    if (!view->isTeacher())
        return LiveShareRefusal{"forbidden", "only the class's teacher shares a live session with it"};
    if (view->info.archived) return LiveShareRefusal{"archived", "the class is archived"};
    return std::nullopt;
}

std::optional<std::int64_t> watchingClass(LabStore& labs, const User& who, const std::vector<std::int64_t>& sharedClasses)
{
    for (const std::int64_t classId : sharedClasses)
        if (classFor(labs, who, classId)) return classId;
    return std::nullopt;
}

std::string liveSetLockProblem(LabStore& labs, const User& who, std::int64_t modelId, const std::string& name,
                               double value)
{
    const CopyAccess access = copyAccess(labs, who, modelId);
    if (access.kind == CopyAccess::Kind::None) return "you are no longer in this assignment's class";
    // A supervisor's run of a copy changes the run, never the copy: as with any model they read.
    if (!access.lock) return "";
    // A live name ("Step.y_A", "Sub$Gain.k") is the path the lock lists parameters by.
    return access.lock->numberProblem(name, value);
}

std::vector<protocol::LiveValue> changeableLiveValues(LabStore& labs, const User& who, std::int64_t modelId,
                                                      const std::vector<LiveValue>& values)
{
    const CopyAccess access = copyAccess(labs, who, modelId);
    std::vector<protocol::LiveValue> changeable;
    for (const LiveValue& v : values) {
        protocol::LiveValue item{.name = v.path, .value = v.value, .unit = v.unit, .min = {}, .max = {}};
        if (access.lock) {
            const AllowedParameter* allowed = access.lock->find(v.path);
            if (!allowed) continue;
            item.min = allowed->min;
            item.max = allowed->max;
        }
        changeable.push_back(std::move(item));
    }
    return changeable;
}

} // namespace tlmhub::server
