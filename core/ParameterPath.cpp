#include "core/ParameterPath.h"

#include "core/ParameterEvaluator.h"
#include "core/System.h"

#include <cmath>

namespace tlmhub {

namespace {

// The component "Sub$Comp" (`owner`) names, walking subsystems from the root. Failures name
// the part that is missing and carry the whole parameter path.
Result<Component*> componentAt(System& root, const std::string& owner, const std::string& path)
{
    System* system = &root;
    std::size_t begin = 0;
    for (std::size_t dollar; (dollar = owner.find('$', begin)) != std::string::npos; begin = dollar + 1) {
        const std::string name = owner.substr(begin, dollar - begin);
        System* sub = system->subsystem(name);
        if (!sub)
            return Status{StatusCode::UnknownParameter,
                          "no subsystem '" + name + "' in system '" + system->name() + "'", path};
        system = sub;
    }
    const std::string name = owner.substr(begin);
    Component* c = system->component(name);
    if (!c)
        return Status{StatusCode::UnknownParameter,
                      "no component '" + name + "' in system '" + system->name() + "'", path};
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
    Result<Component*> owner = componentAt(root, path.substr(0, dot), path);
    if (!owner) return owner.status();
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
    if (const Status assigned = assignParameter(*found->owner, *found->parameter, value); !assigned)
        return {StatusCode::InvalidParameter, "parameter '" + path + "' = '" + value + "': " + assigned.message(),
                path};
    return Status::ok();
}

Status finiteValueStatus(const Parameter& parameter)
{
    if (parameter.type != ParameterType::Double || !parameter.doubleTarget || std::isfinite(*parameter.doubleTarget))
        return Status::ok();
    return {StatusCode::InvalidParameter, "'" + parameter.value + "' is not a finite number"};
}

Status assignParameter(Component& owner, Parameter& parameter, const std::string& value)
{
    const std::string previous = parameter.value;
    parameter.value = value;
    Status evaluated = ParameterEvaluator::evaluate(owner, parameter);
    if (evaluated) evaluated = finiteValueStatus(parameter);
    // A parameter may say where the component's ports come from (an FMU's path).
    if (evaluated) evaluated = owner.loadExternalDefinition();
    if (!evaluated) {
        parameter.value = previous;
        ParameterEvaluator::evaluate(owner, parameter);   // its target holds the old value again
    }
    return evaluated;
}

} // namespace tlmhub
