#pragma once
// A deep copy of a model's system tree: new components from the factory, given the same
// names, parameter values, settings and preserved file content, connected the same way.
// The copy is what saving the model and loading the file back would give, without the
// text in between (tests/core/TestModel.cpp checks both against every shared model).
#include "core/Status.h"
#include "core/System.h"

#include <memory>

namespace tlmhub {

// unknown_component_type for a component the factory cannot make (one built outside it);
// invalid_model for a parameter or connection the copy does not take.
Result<std::unique_ptr<System>> copySystem(const System& root);

} // namespace tlmhub
