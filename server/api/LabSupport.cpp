#include "server/api/LabSupport.h"

#include "server/store/UnixTime.h"

namespace tlmhub::server {

std::optional<ClassView> visibleClass(Services& s, const Call& call)
{
    const auto it = call.params.path.find("id");
    const auto id = it == call.params.path.end() ? std::nullopt : parseId(it->second);
    if (!id) return std::nullopt;
    return classFor(s.labs.store(), call.who(), *id);
}

std::optional<AssignmentView> visibleAssignment(Services& s, const Call& call)
{
    const auto it = call.params.path.find("id");
    const auto id = it == call.params.path.end() ? std::nullopt : parseId(it->second);
    if (!id) return std::nullopt;
    return assignmentFor(s.labs.store(), call.who(), *id, unixNow());
}

Response labNotFound(const std::string& what)
{
    return apiError(http::status::not_found, "not_found", "no such " + what);
}

Response labArchived()
{
    return apiError(http::status::conflict, "archived", "the class is archived: it is read-only");
}

Response labErrorResponse(const LabError& error)
{
    if (error.code == "forbidden") return apiError(http::status::forbidden, error.code, error.message);
    if (error.code == "conflict" || error.code == "archived" || error.code == "deadline_passed")
        return apiError(http::status::conflict, error.code, error.message);
    return refusal(error.code, error.message);
}

nlohmann::json checksJson(const std::vector<AssignmentCheck>& checks, bool everything)
{
    nlohmann::json list = nlohmann::json::array();
    for (const AssignmentCheck& c : checks) {
        nlohmann::json entry = {{"name", c.name}, {"points", c.points}, {"pretest", c.pretest}};
        // Students see what a pretest asks; the hand-in checks only by name and points.
        if (everything || c.pretest) entry["definition"] = nlohmann::json::parse(c.definition, nullptr, false);
        list.push_back(std::move(entry));
    }
    return list;
}

} // namespace tlmhub::server
