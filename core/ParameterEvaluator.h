#pragma once
// Evaluation of parameter value strings (core.md §5.2): numbers directly, expressions with
// muParser, names resolved as Hopsan resolves them (self.X, then system parameters upwards).
#include "core/Status.h"

#include <string>

namespace tlmhub {

class Component;
struct Parameter;

namespace ParameterEvaluator {

// Evaluate `param` in the context of `owner` and write the result into its target.
// Fails with invalid_parameter, the message naming what is wrong (unknown name, syntax,
// type) and the path "Sub$Comp.param".
Status evaluate(Component& owner, Parameter& param);

// Evaluate a double expression in the context of `owner` without touching any parameter.
Result<double> evaluateExpression(Component& owner, const std::string& expression);

} // namespace ParameterEvaluator
} // namespace tlmhub
