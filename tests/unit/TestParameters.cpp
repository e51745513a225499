// Parameter evaluation (core.md §5): numbers, expressions via muParser, system parameters
// up the hierarchy, self references, and clear errors.
#include "TestHelpers.h"

#include "core/ParameterEvaluator.h"

using namespace tlmhub;
using namespace tlmhub::test;

TEST(Parameters, NumbersExpressionsAndSystemParameters)
{
    System root;
    std::string err;
    ASSERT_TRUE(root.setSystemParameter("A2", "0.002", "double", "", "m^2", false, err)) << err;
    ASSERT_TRUE(root.setSystemParameter("k", "2*A2 + 1", "double", "", "", false, err)) << err;
    add(root, "SignalGain", "G");
    Component* g = root.component("G");
    Parameter* p = g->parameters().find("k#Value");
    ASSERT_TRUE(p);
    double v = 0;
    p->value = "-A2";
    ASSERT_TRUE(ParameterEvaluator::evaluateExpression(*g, p->value, v, err)) << err;
    EXPECT_DOUBLE_EQ(v, -0.002);
    ASSERT_TRUE(ParameterEvaluator::evaluateExpression(*g, "k", v, err)) << err;
    EXPECT_DOUBLE_EQ(v, 1.004);
    ASSERT_TRUE(ParameterEvaluator::evaluateExpression(*g, "sin(pi/2)^2 + max(1, 3)", v, err)) << err;
    EXPECT_DOUBLE_EQ(v, 4.0);
    ASSERT_TRUE(ParameterEvaluator::evaluateExpression(*g, "log(exp(2))", v, err)) << err;
    EXPECT_DOUBLE_EQ(v, 2.0);
}

TEST(Parameters, NestedSystemsSeeOuterParameters)
{
    System root;
    std::string err;
    ASSERT_TRUE(root.setSystemParameter("Force", "1000", "double", "", "N", false, err));
    auto sub = std::make_unique<System>();
    sub->setNameRaw("Sub");
    System* subRaw = sub.get();
    root.addComponent(std::move(sub));
    add(*subRaw, "SignalGain", "G");
    Component* g = subRaw->component("G");
    double v = 0;
    ASSERT_TRUE(ParameterEvaluator::evaluateExpression(*g, "Force/2", v, err)) << err;
    EXPECT_DOUBLE_EQ(v, 500.0);
}

TEST(Parameters, SelfReferenceReadsOwnParameter)
{
    System root;
    add(root, "SignalGain", "G");
    Component* g = root.component("G");
    g->parameters().find("k#Value")->value = "4";
    double v = 0;
    std::string err;
    ASSERT_TRUE(ParameterEvaluator::evaluateExpression(*g, "self.k*2", v, err)) << err;
    EXPECT_DOUBLE_EQ(v, 8.0);
}

TEST(Parameters, UnknownNameAndSyntaxErrorsAreReported)
{
    System root;
    add(root, "SignalGain", "G");
    Component* g = root.component("G");
    double v = 0;
    std::string err;
    EXPECT_FALSE(ParameterEvaluator::evaluateExpression(*g, "nosuchname*2", v, err));
    EXPECT_NE(err.find("nosuchname"), std::string::npos) << err;
    EXPECT_FALSE(ParameterEvaluator::evaluateExpression(*g, "2*(3", v, err));
    EXPECT_FALSE(err.empty());
    // The model check names the component and parameter of a bad value.
    g->parameters().find("k#Value")->value = "oops";
    EXPECT_FALSE(root.checkModel(err));
    EXPECT_NE(err.find("k#Value"), std::string::npos) << err;
}

TEST(Parameters, ReferenceLoopIsStopped)
{
    System root;
    std::string err;
    ASSERT_TRUE(root.setSystemParameter("a", "b+1", "double", "", "", false, err));
    ASSERT_TRUE(root.setSystemParameter("b", "a+1", "double", "", "", false, err));
    add(root, "SignalGain", "G");
    double v = 0;
    EXPECT_FALSE(ParameterEvaluator::evaluateExpression(*root.component("G"), "a", v, err));
}

TEST(Parameters, ExpressionValueReachesTheSimulation)
{
    System root;
    std::string err;
    ASSERT_TRUE(root.setSystemParameter("gain", "2.5", "double", "", "", false, err));
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
    std::string err;
    ASSERT_TRUE(root.setSystemParameter("a", "b+c", "double", "", "", false, err));
    ASSERT_TRUE(root.setSystemParameter("b", "a+c", "double", "", "", false, err));
    ASSERT_TRUE(root.setSystemParameter("c", "a+b", "double", "", "", false, err));
    add(root, "SignalGain", "G");
    double v = 0;
    EXPECT_FALSE(ParameterEvaluator::evaluateExpression(*root.component("G"), "a", v, err));
    EXPECT_NE(err.find("reference loop"), std::string::npos) << err;
}
