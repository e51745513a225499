#include "core/ParameterPath.h"

#include "core/ParameterEvaluator.h"
#include "core/System.h"

namespace tlmhub {

namespace {

// The component "Sub$Comp" names, walking subsystems from the root. Failures name the part
// that is missing; the caller gives them the whole path.
Result<Component*> componentAt(System& root, const std::string& path)
{
    System* system = &root;
    std::size_t begin = 0;
    for (std::size_t dollar; (dollar = path.find('$', begin)) != std::string::npos; begin = dollar + 1) {
        const std::string name = path.substr(begin, dollar - begin);
        System* sub = system->subsystem(name);
        if (!sub)
            return Status{StatusCode::UnknownParameter,
                          "no subsystem '" + name + "' in system '" + system->name() + "'"};
        system = sub;
    }
    const std::string name = path.substr(begin);
    Component* c = system->component(name);
    if (!c)
        return Status{StatusCode::UnknownParameter,
                      "no component '" + name + "' in system '" + system->name() + "'"};
    return c;
}

} // namespace

Result<ParameterRef> findParameter(System& root, const std::string& path)
{
    const std::size_t dot = path.find('.');
    if (dot == std::string::npos) {
        Parameter* p = root.parameters().find(path);
        if (!p || p->isStartValue)
            return Status{StatusCode::UnknownParameter,
                          "no system parameter '" + path + "' in system '" + root.name() + "'", path};
        return ParameterRef{&root, p};
    }
    Result<Component*> owner = componentAt(root, path.substr(0, dot));
    if (!owner) return Status{owner.status().code(), owner.status().message(), path};
    const std::string name = path.substr(dot + 1);
    Parameter* p = (*owner)->parameters().find(name);
    if (!p) p = (*owner)->parameters().find(name + "#Value");
    if (!p)
        return Status{StatusCode::UnknownParameter,
                      "component '" + (*owner)->name() + "' has no parameter '" + name + "'", path};
    return ParameterRef{*owner, p};
}

Status setParameterValue(System& root, const std::string& path, const std::string& value)
{
    Result<ParameterRef> found = findParameter(root, path);
    if (!found) return found.status();
    Parameter& p = *found->parameter;
    const std::string previous = p.value;
    p.value = value;
    if (const Status evaluated = ParameterEvaluator::evaluate(*found->owner, p); !evaluated) {
        p.value = previous;
        ParameterEvaluator::evaluate(*found->owner, p);   // its target holds the old value again
        return {StatusCode::InvalidParameter,
                "parameter '" + path + "' = '" + value + "': " + evaluated.message(), path};
    }
    return Status::ok();
}

} // namespace tlmhub
