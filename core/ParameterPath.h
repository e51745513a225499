#pragma once
// Parameters named by path, the one syntax of the run API, server jobs and the CLI:
//   "Comp.param"       a parameter of a component of the root system
//   "Sub$Comp.param"   of a component inside subsystem Sub (more '$' for deeper nesting)
//   "Sub.param"        a subsystem's own system parameter
//   "param"            a system parameter of the root
// "Comp.x" also finds the start value "x#Value" of an input variable.
#include "core/Status.h"

#include <string>

namespace tlmhub {

class Component;
class System;
struct Parameter;

struct ParameterRef {
    Component* owner = nullptr;
    Parameter* parameter = nullptr;
};

// unknown_parameter naming the part of the path that names nothing.
Result<ParameterRef> findParameter(System& root, const std::string& path);

// Sets the value string and evaluates it in its owner's scope. A value that does not
// evaluate is refused (invalid_parameter) and the old value is kept.
Status setParameterValue(System& root, const std::string& path, const std::string& value);

// The same for a parameter already found: a refused value leaves the old string and its
// evaluated value in place. The failure is the evaluator's, without the path, or the
// component's when it cannot load its external definition with the new value
// (Component::loadExternalDefinition: model editing declares an FMU's ports this way).
// A number parameter's value must come out finite: "1e400", "nan" or "1/0" are refused
// (a model file that holds one still loads, as in Hopsan).
Status assignParameter(Component& owner, Parameter& parameter, const std::string& value);

// invalid_parameter when `parameter`, just evaluated, is a number parameter whose value is
// not a finite number; ok otherwise.
Status finiteValueStatus(const Parameter& parameter);

} // namespace tlmhub
