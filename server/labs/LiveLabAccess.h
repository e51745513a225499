#pragma once
// Live sessions in a lab (docs/live-sessions.md, "In a lab"): who may share a session with a
// class and who may watch it there, and what a student's session on a locked copy may change.
// The rules of LabAccess.h applied to live sessions; the WebSocket (WsApi) asks here.
#include "server/labs/LabAccess.h"
#include "server/protocol/Messages.generated.h"

#include "core/Simulation.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

// Why `who` may not share a live session with class `classId` (empty code: they may): the
// class's teacher may (an administrator is teacher in every class); a class they are not in
// is not_found, one they are in but do not teach forbidden, an archived one archived.
struct LiveShareRefusal {
    std::string code, message;
};
std::optional<LiveShareRefusal> liveShareRefusal(LabStore& labs, const User& who, std::int64_t classId);

// The class through which `who` may watch a session shared with `sharedClasses`: the first
// one they are a member of (any role). Nullopt: none, and the session is not there for them.
std::optional<std::int64_t> watchingClass(LabStore& labs, const User& who, const std::vector<std::int64_t>& sharedClasses);

// "" when `who` may live.set `name` to `value` in a session of model `modelId`, else why not
// (answered as locked): on an assignment's copy with edit mode "parameters", its student may
// change only the listed parameters within their bounds, as parameter.set on the copy; a
// student no longer in the class changes nothing. Asked on every set, so a lock or a
// membership changed while the session runs holds from the next set on.
std::string liveSetLockProblem(LabStore& labs, const User& who, std::int64_t modelId, const std::string& name,
                               double value);

// What live.start lists as changeable for `who` (live_values): every live value, but on a
// locked copy (for its student) only the listed ones, each with the assignment's bounds.
std::vector<protocol::LiveValue> changeableLiveValues(LabStore& labs, const User& who, std::int64_t modelId,
                                                      const std::vector<LiveValue>& values);

} // namespace tlmhub::server
