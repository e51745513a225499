#pragma once
// Evaluation of parameter value strings (core.md §5.2): numbers directly, expressions with
// muParser, names resolved as Hopsan resolves them (self.X, then system parameters upwards).
#include "core/Status.h"

#include <cstddef>
#include <string>
#include <unordered_map>

namespace tlmhub {

class Component;
struct Parameter;

namespace ParameterEvaluator {

// Expression evaluations one pass may make unless its caller says otherwise; process-wide
// (the server's --max-parameter-evaluations). The default admits every shared model many
// times over (TestParameters.cpp checks a hundred times).
constexpr std::size_t kDefaultBudget = 100'000;
void setDefaultBudget(std::size_t evaluations);
std::size_t defaultBudget();

// One evaluation pass over a model whose values do not change meanwhile. An expression
// parameter's value is computed once and then remembered, so a chain where each level names
// two of the level below stays linear instead of doubling per level; and the pass fails once
// it has evaluated `budget` expressions.
struct Pass {
    explicit Pass(std::size_t budget = defaultBudget()) : budget(budget) {}
    std::size_t budget;
    std::size_t evaluations = 0;
    std::unordered_map<const Parameter*, double> values;
};

// Evaluate `param` in the context of `owner` and write the result into its target.
// Fails with invalid_parameter, the message naming what is wrong (unknown name, syntax,
// type, the pass's budget spent) and the path "Sub$Comp.param".
Status evaluate(Component& owner, Parameter& param, Pass& pass);
// The same in a pass of its own.
Status evaluate(Component& owner, Parameter& param);

// Evaluate a double expression in the context of `owner` without touching any parameter.
Result<double> evaluateExpression(Component& owner, const std::string& expression);

} // namespace ParameterEvaluator
} // namespace tlmhub
