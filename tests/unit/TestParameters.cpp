// Parameter evaluation (core.md §5): numbers, expressions via muParser, system parameters
// up the hierarchy, self references, and clear errors.
#include "TestHelpers.h"

#include "core/ParameterEvaluator.h"

#include <cmath>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

// The value of an expression that must evaluate (NaN and a test failure otherwise).
double evaluated(Component& owner, const std::string& expression)
{
    const Result<double> value = ParameterEvaluator::evaluateExpression(owner, expression);
    if (value) return *value;
    ADD_FAILURE() << expression << ": " << value.status().message();
    return std::nan("");
}

// Why an expression that must not evaluate does not.
std::string failureOf(const Result<double>& value)
{
    EXPECT_FALSE(value) << "the expression should not evaluate";
    EXPECT_EQ(value.status().code(), StatusCode::InvalidParameter);
    return value.status().message();
}

} // namespace

TEST(Parameters, NumbersExpressionsAndSystemParameters)
{
    System root;
    ASSERT_TRUE(isOk(root.setSystemParameter("A2", "0.002", "double", "", "m^2", false)));
    ASSERT_TRUE(isOk(root.setSystemParameter("k", "2*A2 + 1", "double", "", "", false)));
    add(root, "SignalGain", "G");
    Component* g = root.component("G");
    Parameter* p = g->parameters().find("k#Value");
    ASSERT_TRUE(p);
    p->value = "-A2";
    EXPECT_DOUBLE_EQ(evaluated(*g, p->value), -0.002);
    EXPECT_DOUBLE_EQ(evaluated(*g, "k"), 1.004);
    EXPECT_DOUBLE_EQ(evaluated(*g, "sin(pi/2)^2 + max(1, 3)"), 4.0);
    EXPECT_DOUBLE_EQ(evaluated(*g, "log(exp(2))"), 2.0);
}

TEST(Parameters, NestedSystemsSeeOuterParameters)
{
    System root;
    ASSERT_TRUE(isOk(root.setSystemParameter("Force", "1000", "double", "", "N", false)));
    auto sub = std::make_unique<System>();
    sub->setNameRaw("Sub");
    System* subRaw = sub.get();
    root.addComponent(std::move(sub));
    add(*subRaw, "SignalGain", "G");
    Component* g = subRaw->component("G");
    EXPECT_DOUBLE_EQ(evaluated(*g, "Force/2"), 500.0);
}

TEST(Parameters, SelfReferenceReadsOwnParameter)
{
    System root;
    add(root, "SignalGain", "G");
    Component* g = root.component("G");
    g->parameters().find("k#Value")->value = "4";
    EXPECT_DOUBLE_EQ(evaluated(*g, "self.k*2"), 8.0);
}

TEST(Parameters, UnknownNameAndSyntaxErrorsAreReported)
{
    System root;
    add(root, "SignalGain", "G");
    Component* g = root.component("G");
    std::string err = failureOf(ParameterEvaluator::evaluateExpression(*g, "nosuchname*2"));
    EXPECT_NE(err.find("nosuchname"), std::string::npos) << err;
    err = failureOf(ParameterEvaluator::evaluateExpression(*g, "2*(3"));
    EXPECT_FALSE(err.empty());
    // The model check names the component and parameter of a bad value.
    g->parameters().find("k#Value")->value = "oops";
    const Status checked = root.check();
    EXPECT_EQ(checked.code(), StatusCode::InvalidParameter);
    EXPECT_EQ(checked.path(), "G.k#Value");
    EXPECT_NE(checked.message().find("k#Value"), std::string::npos) << checked.message();
}

TEST(Parameters, ReferenceLoopIsStopped)
{
    System root;
    ASSERT_TRUE(isOk(root.setSystemParameter("a", "b+1", "double", "", "", false)));
    ASSERT_TRUE(isOk(root.setSystemParameter("b", "a+1", "double", "", "", false)));
    add(root, "SignalGain", "G");
    failureOf(ParameterEvaluator::evaluateExpression(*root.component("G"), "a"));
}

TEST(Parameters, ExpressionValueReachesTheSimulation)
{
    System root;
    ASSERT_TRUE(isOk(root.setSystemParameter("gain", "2.5", "double", "", "", false)));
    add(root, "SignalConstant", "C");
    add(root, "SignalGain", "G");
    add(root, "SignalSink", "S");
    connectOk(root, "C", "y", "G", "in");
    connectOk(root, "G", "out", "S", "in");
    setParam(root, "C", "y#Value", "2");
    setParam(root, "G", "k#Value", "gain*2");
    ASSERT_TRUE(run(root, 0, 0.01, 0.001, 11));
    EXPECT_DOUBLE_EQ(root.component("G")->port("out")->node()->value(0), 10.0);
}

// Found by fuzz/FuzzParameterExpression: loops were stopped only by the depth limit, 250
// levels down every branch, so three parameters referring to each other took 2^250 steps.
TEST(Parameters, LoopOverThreeParametersFailsAtOnce)
{
    System root;
    ASSERT_TRUE(isOk(root.setSystemParameter("a", "b+c", "double", "", "", false)));
    ASSERT_TRUE(isOk(root.setSystemParameter("b", "a+c", "double", "", "", false)));
    ASSERT_TRUE(isOk(root.setSystemParameter("c", "a+b", "double", "", "", false)));
    add(root, "SignalGain", "G");
    std::string err = failureOf(ParameterEvaluator::evaluateExpression(*root.component("G"), "a"));
    EXPECT_NE(err.find("reference loop"), std::string::npos) << err;
}
