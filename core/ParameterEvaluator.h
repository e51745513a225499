#pragma once
// Evaluation of parameter value strings (core.md §5.2): numbers directly, expressions with
// muParser, names resolved as Hopsan resolves them (self.X, then system parameters upwards).
#include <string>

namespace tlmhub {

class Component;
struct Parameter;

namespace ParameterEvaluator {

// Evaluate `param` in the context of `owner` and write the result into its target.
// Returns false with `error` naming what is wrong (unknown name, syntax, type).
bool evaluate(Component& owner, Parameter& param, std::string& error);

// Evaluate a double expression in the context of `owner` without touching any parameter.
bool evaluateExpression(Component& owner, const std::string& expression, double& result,
                        std::string& error);

} // namespace ParameterEvaluator
} // namespace tlmhub
