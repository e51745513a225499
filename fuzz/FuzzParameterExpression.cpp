// Fuzzes parameter value strings (ParameterEvaluator): the input is up to three lines, the
// values of system parameters `a` and `b` (which may refer to each other) and an expression
// evaluated in a component of that system, both directly and as the component's parameter.
#include "core/ComponentFactory.h"
#include "core/ParameterEvaluator.h"
#include "core/System.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::string a, b, expression;
    std::getline(in, a);
    std::getline(in, b);
    std::getline(in, expression, '\0');

    tlmhub::System root;
    root.setSystemParameter("a", a, "double", "", "", false);
    root.setSystemParameter("b", b, "double", "", "", false);
    auto gain = tlmhub::ComponentFactory::instance().create("SignalGain");
    gain->setNameRaw("G");
    root.addComponent(std::move(gain));
    tlmhub::Component& g = *root.component("G");

    tlmhub::ParameterEvaluator::evaluateExpression(g, expression);
    tlmhub::Parameter& k = *g.parameters().find("k#Value");
    k.value = expression;
    tlmhub::ParameterEvaluator::evaluate(g, k);
    return 0;
}
