// Parameter paths (core/ParameterPath.h): the syntax shared by the run API, server jobs and
// studies, on a model with two copies of one subsystem.
#include "TestHelpers.h"

#include "core/ParameterPath.h"
#include "core/ParameterTexts.h"
#include "core/hmf/HmfLoader.h"

#include <filesystem>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

class ParameterPath : public ::testing::Test {
protected:
    void SetUp() override
    {
        const std::string path = sharedDir() + "/hopsan-models/Example Models/Sub System Example.hmf";
        ASSERT_TRUE(std::filesystem::exists(path)) << "missing shared model " << path;
        LoadedModel model = loadHmfFile(path);
        ASSERT_FALSE(model.hasErrors()) << model.firstError();
        root = std::move(model.root);
    }
    const std::string& value(System& system, const std::string& component, const std::string& name)
    {
        return system.component(component)->parameters().find(name)->value;
    }
    System& servo(const std::string& name) { return *root->subsystem(name); }

    std::unique_ptr<System> root;
};

} // namespace

TEST_F(ParameterPath, NamesComponentsSubsystemsAndSystemParameters)
{
    EXPECT_TRUE(isOk(setParameterValue(*root, "Servo1$Translational_Mass.m", "400")));
    EXPECT_TRUE(isOk(setParameterValue(*root, "Servo1.PGain", "0.01")));          // a subsystem's own
    EXPECT_TRUE(isOk(setParameterValue(*root, "Servo1$Gain.k", "PGain * 2")));    // its own scope
    EXPECT_TRUE(isOk(setParameterValue(*root, "Force", "2000")));                 // the root's
    EXPECT_EQ(value(servo("Servo1"), "Translational_Mass", "m"), "400");
    EXPECT_EQ(servo("Servo1").parameters().find("PGain")->value, "0.01");
    EXPECT_EQ(value(servo("Servo1"), "Gain", "k#Value"), "PGain * 2");   // "k" finds the input's start value
    EXPECT_EQ(root->parameters().find("Force")->value, "2000");
    EXPECT_EQ(value(servo("Servo2"), "Translational_Mass", "m"), "200");   // the other copy is untouched

    Result<ParameterRef> found = findParameter(*root, "Servo2$Gain.k");
    ASSERT_TRUE(found);
    EXPECT_EQ(found->owner, servo("Servo2").component("Gain"));
    EXPECT_EQ(found->parameter->name, "k#Value");
}

// What a run used is listed by path (core/ParameterTexts.h); each path finds its parameter.
TEST_F(ParameterPath, EveryParameterTextIsListedUnderAPathThatFindsIt)
{
    ASSERT_TRUE(isOk(setParameterValue(*root, "Servo1$Gain.k", "PGain * 2")));
    const auto texts = parameterTexts(*root);
    EXPECT_EQ(texts.at("Force"), root->parameters().find("Force")->value);
    EXPECT_EQ(texts.at("Servo1.PGain"), servo("Servo1").parameters().find("PGain")->value);
    EXPECT_EQ(texts.at("Servo1$Gain.k#Value"), "PGain * 2");
    EXPECT_EQ(texts.at("Servo2$Translational_Mass.m"), "200");
    std::size_t count = 0;
    for (const auto& [path, text] : texts) {
        Result<ParameterRef> found = findParameter(*root, path);
        ASSERT_TRUE(found) << path;
        EXPECT_EQ(found->parameter->value, text) << path;
        ++count;
    }
    EXPECT_GT(count, 20u);
}

TEST_F(ParameterPath, APathThatNamesNothingSaysWhichPartIsMissing)
{
    const Status noComponent = setParameterValue(*root, "Servo1$NoSuch.m", "1");
    EXPECT_EQ(noComponent.code(), StatusCode::UnknownParameter);
    EXPECT_EQ(noComponent.path(), "Servo1$NoSuch.m");
    EXPECT_NE(noComponent.message().find("no component 'NoSuch'"), std::string::npos) << noComponent.message();
    const Status noSubsystem = setParameterValue(*root, "NoSuch$Gain.k", "1");
    EXPECT_NE(noSubsystem.message().find("no subsystem 'NoSuch'"), std::string::npos) << noSubsystem.message();
    EXPECT_EQ(setParameterValue(*root, "Servo1$Gain.nope", "1").code(), StatusCode::UnknownParameter);
    EXPECT_EQ(setParameterValue(*root, "NoSystemParameter", "1").code(), StatusCode::UnknownParameter);
}

TEST_F(ParameterPath, AValueThatDoesNotEvaluateIsRefusedAndTheOldOneKept)
{
    ASSERT_TRUE(isOk(setParameterValue(*root, "Servo1$Gain.k", "PGain * 2")));
    const Status refused = setParameterValue(*root, "Servo1$Gain.k", "Force2 * 2");   // unknown name
    EXPECT_EQ(refused.code(), StatusCode::InvalidParameter);
    EXPECT_NE(refused.message().find("Force2"), std::string::npos) << refused.message();
    EXPECT_EQ(value(servo("Servo1"), "Gain", "k#Value"), "PGain * 2");
}

// Issue 38: a number that is not finite ("1e400" reads as infinity) is refused wherever a
// value is set, literal or computed, for component and system parameters alike, naming the
// parameter; the old value stays. Finite extremes are values like any other.
TEST_F(ParameterPath, ANumberThatIsNotFiniteIsRefusedNamingTheParameter)
{
    for (const char* notFinite : {"1e400", "-1e400", "nan", "-nan", "inf", "1/0", "PGain * 1e300 * 1e300"}) {
        const Status refused = setParameterValue(*root, "Servo1$Translational_Mass.m", notFinite);
        EXPECT_EQ(refused.code(), StatusCode::InvalidParameter) << notFinite;
        EXPECT_NE(refused.message().find("Servo1$Translational_Mass.m"), std::string::npos) << refused.message();
        EXPECT_NE(refused.message().find("not a finite number"), std::string::npos) << refused.message();
        EXPECT_EQ(value(servo("Servo1"), "Translational_Mass", "m"), "200") << notFinite;
        EXPECT_EQ(setParameterValue(*root, "Force", notFinite).code(), StatusCode::InvalidParameter) << notFinite;
    }
    EXPECT_NE(root->parameters().find("Force")->value, "1e400");
    EXPECT_TRUE(isOk(setParameterValue(*root, "Servo1$Translational_Mass.m", "1e300")));
    EXPECT_TRUE(isOk(setParameterValue(*root, "Force", "-1.5e+300")));
}
