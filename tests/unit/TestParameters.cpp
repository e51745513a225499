// Parameter evaluation (core.md §5): numbers, expressions via muParser, system parameters
// up the hierarchy, self references, and clear errors.
#include "TestHelpers.h"

#include "core/ParameterEvaluator.h"
#include "core/hmf/HmfLoader.h"

#include <cmath>
#include <filesystem>

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

namespace {

// a0 = 1, b0 = 2, and at each level aK = a(K-1) + b(K-1), bK = a(K-1) - b(K-1): every level
// names both of the level below, so evaluating without remembering doubles per level. Two
// levels double both values: a(2n) = 2^n, b(2n) = 2^(n+1).
void addDoublingChain(System& root, int levels)
{
    ASSERT_TRUE(isOk(root.setSystemParameter("a0", "1", "double", "", "", false)));
    ASSERT_TRUE(isOk(root.setSystemParameter("b0", "2", "double", "", "", false)));
    for (int k = 1; k <= levels; ++k) {
        const std::string below = std::to_string(k - 1);
        ASSERT_TRUE(isOk(root.setSystemParameter("a" + std::to_string(k), "a" + below + "+b" + below, "double", "", "", false)));
        ASSERT_TRUE(isOk(root.setSystemParameter("b" + std::to_string(k), "a" + below + "-b" + below, "double", "", "", false)));
    }
}

// Every parameter of `system` and of everything inside it, in `pass`.
Status evaluateEveryParameter(System& system, ParameterEvaluator::Pass& pass)
{
    for (const auto& param : system.parameters().all())
        if (Status evaluated = ParameterEvaluator::evaluate(system, *param, pass); !evaluated) return evaluated;
    for (Component* c : system.componentsInOrder()) {
        if (c->isSystem()) {
            if (Status evaluated = evaluateEveryParameter(*static_cast<System*>(c), pass); !evaluated) return evaluated;
            continue;
        }
        for (const auto& param : c->parameters().all())
            if (Status evaluated = ParameterEvaluator::evaluate(*c, *param, pass); !evaluated) return evaluated;
    }
    return Status::ok();
}

} // namespace

// Issue 37 H1: 16 such levels took 9.5 s to upload, and every further level twice as long.
TEST(Parameters, ReferencesNamingTwoOfTheLevelBelowAreEvaluatedOnceEach)
{
    constexpr int kLevels = 60;   // 2^60 evaluations without remembering
    System root;
    addDoublingChain(root, kLevels);
    ParameterEvaluator::Pass pass;
    double a = 0, b = 0;
    Parameter* top = root.parameters().find("a" + std::to_string(kLevels));
    ASSERT_NE(top, nullptr);
    top->doubleTarget = &a;
    ASSERT_TRUE(isOk(ParameterEvaluator::evaluate(root, *top, pass)));
    Parameter* other = root.parameters().find("b" + std::to_string(kLevels));
    other->doubleTarget = &b;
    ASSERT_TRUE(isOk(ParameterEvaluator::evaluate(root, *other, pass)));
    EXPECT_EQ(a, std::ldexp(1.0, kLevels / 2));
    EXPECT_EQ(b, std::ldexp(1.0, kLevels / 2 + 1));
    EXPECT_EQ(pass.evaluations, std::size_t{2 * kLevels}) << "one evaluation per expression parameter";
    // A whole check (one pass over the model) too.
    EXPECT_TRUE(isOk(root.check()));
}

TEST(Parameters, APassStopsAtItsBudgetNamingTheParameter)
{
    System root;
    addDoublingChain(root, 20);
    ParameterEvaluator::Pass pass(25);
    const Status status = evaluateEveryParameter(root, pass);
    ASSERT_FALSE(isOk(status));
    EXPECT_EQ(status.code(), StatusCode::InvalidParameter);
    EXPECT_NE(status.message().find("more than 25 parameter expressions"), std::string::npos) << status.message();
    EXPECT_NE(status.message().find("evaluation limit"), std::string::npos) << status.message();
    // In the order added: a1..a12 and b1..b12 take 24 evaluations, a13 the 25th, and b13
    // would need a 26th.
    EXPECT_EQ(status.path(), "b13");
    // The process-wide default applies to every check of a model (the server's flag).
    ParameterEvaluator::setDefaultBudget(25);
    const Status checked = root.check();
    ParameterEvaluator::setDefaultBudget(ParameterEvaluator::kDefaultBudget);
    EXPECT_NE(checked.message().find("evaluation limit"), std::string::npos) << checked.message();
}

// The default budget admits every shared model a hundred times over.
TEST(Parameters, TheDefaultBudgetAdmitsEverySharedModelAHundredTimes)
{
    std::size_t models = 0, most = 0;
    std::string mostIn;
    for (const char* folder : {"/hopsan-models", "/bench-models"}) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(sharedDir() + folder)) {
            if (entry.path().extension() != ".hmf") continue;
            LoadedModel loaded = loadHmfFile(entry.path().string());
            if (!loaded.root) continue;
            ++models;
            ParameterEvaluator::Pass pass;
            (void)evaluateEveryParameter(*loaded.root, pass);
            if (pass.evaluations > most) {
                most = pass.evaluations;
                mostIn = entry.path().filename().string();
            }
        }
    }
    EXPECT_GT(models, 100u) << "the shared models must be in " << sharedDir();
    RecordProperty("most_expressions", std::to_string(most) + " in " + mostIn);
    EXPECT_LE(most * 100, ParameterEvaluator::kDefaultBudget) << mostIn << " evaluates " << most << " expressions";
}
