// System::group / System::ungroup on shared example models: a grouped model logs exactly
// the same numbers (under the subsystem's variable names), a group that could not run is
// refused without a change, and ungroup gives the original model back.
#include "TestHelpers.h"

#include "core/ParameterEvaluator.h"
#include "core/ResultTable.h"
#include "core/hmf/HmfLoader.h"
#include "core/hmf/HmfSaver.h"

#include <set>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

const std::string kServo = sharedDir() + "/hopsan-models/Example Models/Position Servo.hmf";
const std::string kFeedback = sharedDir() + "/hopsan-models/Example Models/Dynamic Pressure Feedback.hmf";
const std::string kSubsystems = sharedDir() + "/hopsan-models/Example Models/Sub System Example.hmf";
// Its relief valve's setting is the system parameter relief_pressure.
const std::string kPressureBuildUp = std::string(TLMHUB_SOURCE_DIR) + "/examples/pressure-build-up.hmf";

std::unique_ptr<System> load(const std::string& path)
{
    LoadedModel loaded = loadHmfFile(path);
    EXPECT_FALSE(loaded.hasErrors()) << loaded.firstError();
    return std::move(loaded.root);
}

// The subsystem's name, or empty (and a test failure) if grouping failed.
std::string nameOrFailure(const Result<std::string>& grouped)
{
    if (grouped) return *grouped;
    ADD_FAILURE() << describe(grouped.status());
    return {};
}

// Why grouping was refused (a test failure if it was not).
std::string refusal(const Result<std::string>& grouped)
{
    EXPECT_FALSE(grouped) << "grouping should have been refused";
    return grouped.status().message();
}

ResultTable simulate(System& root)
{
    const std::optional<Simulation> sim = runToStop(compile(root));
    if (!sim) return {};
    return ResultTable::fromView(sim->results());
}

// Every variable logged before is logged after, with the grouped components' variables
// under `sub$` (in the system whose variables begin with `within`), and holds exactly the
// same values.
void expectSameResults(const ResultTable& before, const ResultTable& after, const std::string& sub,
                       const std::set<std::string>& grouped, const std::string& within = "")
{
    ASSERT_FALSE(before.columns.empty());
    EXPECT_EQ(before.time, after.time);
    for (const ResultColumn& column : before.columns) {
        std::string name = column.name;
        if (name.rfind(within, 0) == 0) {
            const std::string local = name.substr(within.size());
            if (grouped.count(local.substr(0, local.find_first_of("#$")))) name = within + sub + "$" + local;
        }
        const ResultColumn* now = after.column(name);
        ASSERT_TRUE(now) << "no variable " << name << " after grouping";
        EXPECT_EQ(now->data, column.data) << name;
    }
    if (const ResultColumn* subTime = after.column(within + sub + "$Time")) {
        EXPECT_EQ(subTime->data, before.time);
    }
}

void groupKeepsResults(const std::string& model, const std::vector<std::string>& names, CqsKind kind)
{
    auto original = load(model);
    ASSERT_TRUE(original);
    const ResultTable before = simulate(*original);

    auto root = load(model);
    const std::string sub = nameOrFailure(root->group(names, "Group"));
    ASSERT_EQ(sub, "Group");
    ASSERT_TRUE(root->subsystem(sub));
    EXPECT_EQ(root->subsystem(sub)->kind(), kind);
    const std::set<std::string> grouped(names.begin(), names.end());
    expectSameResults(before, simulate(*root), sub, grouped);

    // The grouped model saves as a model that runs the same.
    LoadedModel reloaded = loadHmfString(saveHmfString(*root), original->modelDirectory, "grouped");
    ASSERT_FALSE(reloaded.hasErrors()) << reloaded.firstError();
    expectSameResults(before, simulate(*reloaded.root), sub, grouped);
}

} // namespace

TEST(Grouping, QTypeHydraulicComponentsKeepEveryResult)
{
    groupKeepsResults(kServo, {"4_3_Servo_Valve", "Pressure_Relief_Valve", "Q_type_Fixed_Displacement_Pump_1"},
                      CqsKind::Q);
}

// A C-type subsystem's power ports have start values of their own, which overwrite the
// inner ones at start; they begin as the inner ones.
TEST(Grouping, CTypeComponentsKeepEveryResult)
{
    groupKeepsResults(kServo, {"Hydraulic_Volume_Multi_Port", "Cylinder_C", "Tank_C_2"}, CqsKind::C);
}

TEST(Grouping, SubsystemsAndSensorsKeepEveryResult)
{
    groupKeepsResults(kSubsystems, {"Servo1", "Servo1_Position"}, CqsKind::Q);
}

TEST(Grouping, GroupedComponentsStillSeeTheSystemParameters)
{
    groupKeepsResults(kPressureBuildUp, {"ReliefValve", "ReturnTank"}, CqsKind::Q);
    auto root = load(kPressureBuildUp);
    const std::string sub = nameOrFailure(root->group({"ReliefValve"}, "Group"));
    ASSERT_FALSE(sub.empty());
    ASSERT_TRUE(isOk(root->setSystemParameter("relief_pressure", "5e6", "double", "", "Pa", false)));
    const Result<double> value =
        ParameterEvaluator::evaluateExpression(*root->subsystem(sub)->component("ReliefValve"), "relief_pressure");
    ASSERT_TRUE(isOk(value.status()));
    EXPECT_EQ(*value, 5e6);
}

// Inside a subsystem, connections to its own system ports cross the new boundary too.
TEST(Grouping, InsideASubsystemKeepsEveryResultAndUngroupsBack)
{
    auto original = load(kSubsystems);
    const ResultTable before = simulate(*original);
    auto root = load(kSubsystems);
    System* servo = root->subsystem("Servo1");
    const std::string sub = nameOrFailure(servo->group({"Subtract", "Gain"}, "Group"));
    ASSERT_EQ(sub, "Group");
    expectSameResults(before, simulate(*root), sub, {"Subtract", "Gain"}, "Servo1$");
    ASSERT_TRUE(isOk(servo->ungroup(sub).status()));
    EXPECT_EQ(saveHmfString(*root), saveHmfString(*original));
}

TEST(Grouping, MultiportKeepsOneSystemPortPerNode)
{
    auto root = load(kServo);
    const std::string sub = nameOrFailure(root->group({"4_3_Servo_Valve", "Pressure_Relief_Valve", "Q_type_Fixed_Displacement_Pump_1"},
                                        "Group"));
    ASSERT_FALSE(sub.empty());
    // Three separate connections to the volume's multiport stay three nodes.
    const Port* volume = root->component("Hydraulic_Volume_Multi_Port")->port("P1");
    ASSERT_EQ(volume->subPorts.size(), 3u);
    std::set<const Node*> nodes;
    for (const auto& p : volume->subPorts) {
        ASSERT_EQ(p->connectedPorts.size(), 1u);
        EXPECT_EQ(p->connectedPorts[0]->component(), root->subsystem(sub));
        nodes.insert(p->node());
    }
    EXPECT_EQ(nodes.size(), 3u);
}

TEST(Grouping, SignalChainKeepsEveryResult)
{
    groupKeepsResults(kFeedback, {"Subtract_1", "Gain_1", "Subtract_2"}, CqsKind::S);
}

TEST(Grouping, UndefinedKindIsRefusedAndTheModelIsUnchanged)
{
    auto root = load(kServo);
    const std::string before = saveHmfString(*root);
    // The mass is Q-type, the cylinder C-type, and both have connections leaving the group.
    EXPECT_NE(refusal(root->group({"Mass", "Cylinder_C"}, "Group")).find("undefined C/Q/S kind"), std::string::npos);
    EXPECT_EQ(saveHmfString(*root), before);
    EXPECT_FALSE(root->component("Group"));
}

TEST(Grouping, ASignalLoopThroughTheRestIsRefused)
{
    auto root = load(kServo);
    const std::string before = saveHmfString(*root);
    // Subtract -> GainP -> Add (and Subtract -> Integrator -> GainI -> Add): without the
    // middle the group would both feed and read it.
    EXPECT_NE(refusal(root->group({"Subtract", "Add"}, "Group")).find("signal loop through '"), std::string::npos);
    EXPECT_EQ(saveHmfString(*root), before);
    // With GainP (and GainI, on the integrator path) it is a chain again.
    EXPECT_EQ(nameOrFailure(root->group({"Subtract", "GainP", "Integrator", "GainI", "Add"}, "Group")), "Group");
}

TEST(Grouping, BadSelectionsAreRefusedAndTheModelIsUnchanged)
{
    auto root = load(kServo);
    const std::string before = saveHmfString(*root);
    EXPECT_NE(refusal(root->group({}, "Group")).find("nothing"), std::string::npos);
    EXPECT_NE(refusal(root->group({"Mass", "Teapot"}, "Group")).find("Teapot"), std::string::npos);
    EXPECT_NE(refusal(root->group({"Mass", "Mass"}, "Group")).find("twice"), std::string::npos);
    EXPECT_EQ(saveHmfString(*root), before);
}

TEST(Grouping, SystemPortsOfTheSystemCannotBeGrouped)
{
    auto root = load(kSubsystems);
    System* servo = root->subsystem("Servo1");
    ASSERT_TRUE(servo);
    Port* sp = nullptr;
    for (Port* p : servo->ports())
        if (p->kind() == PortKind::System) sp = p;
    ASSERT_TRUE(sp);
    EXPECT_NE(refusal(servo->group({sp->name()}, "Group")).find("system port"), std::string::npos);
}

// Components listed one after another in the file come back in their places, so the saved
// model is the original one, GUI data included.
TEST(Grouping, UngroupRestoresTheModel)
{
    for (const auto& [model, names] :
         {std::pair<std::string, std::vector<std::string>>{
              kServo, {"Pressure_Relief_Valve", "Step", "Q_type_Fixed_Displacement_Pump_1"}},
          std::pair<std::string, std::vector<std::string>>{kServo, {"Hydraulic_Volume_Multi_Port", "Sink", "Tank_C_1"}},
          std::pair<std::string, std::vector<std::string>>{kFeedback, {"Gain_1", "Subtract_1", "Subtract_2"}},
          std::pair<std::string, std::vector<std::string>>{kSubsystems, {"Servo1", "Servo2"}}}) {
        SCOPED_TRACE(model);
        auto original = load(model);
        const ResultTable before = simulate(*original);
        auto root = load(model);
            const std::string sub = nameOrFailure(root->group(names, "Group"));
        ASSERT_FALSE(sub.empty());
        const auto ungrouped = root->ungroup(sub);
        ASSERT_TRUE(isOk(ungrouped.status()));
        const std::vector<std::string>& moved = *ungrouped;
        EXPECT_EQ(moved, names);
        EXPECT_EQ(saveHmfString(*root), saveHmfString(*original));
        expectSameResults(before, simulate(*root), "", {});
    }
}

// Components from different places in the file come back side by side; the model runs the same.
TEST(Grouping, UngroupOfScatteredComponentsKeepsEveryResult)
{
    auto original = load(kServo);
    const ResultTable before = simulate(*original);
    auto root = load(kServo);
    const std::string sub =
        nameOrFailure(root->group({"4_3_Servo_Valve", "Pressure_Relief_Valve", "Q_type_Fixed_Displacement_Pump_1"}, "Group"));
    ASSERT_FALSE(sub.empty());
    const auto ungrouped = root->ungroup(sub);
    ASSERT_TRUE(isOk(ungrouped.status()));
    const std::vector<std::string>& moved = *ungrouped;
    EXPECT_EQ(moved, (std::vector<std::string>{"Pressure_Relief_Valve", "Q_type_Fixed_Displacement_Pump_1",
                                                "4_3_Servo_Valve"}));
    expectSameResults(before, simulate(*root), "", {});
}

TEST(Grouping, UngroupMovesSubsystemParametersAndMakesNamesUnique)
{
    auto root = load(kServo);
    const std::string sub = nameOrFailure(root->group({"GainP", "GainI"}, "Gains"));
    ASSERT_FALSE(sub.empty());
    System* gains = root->subsystem(sub);
    ASSERT_TRUE(isOk(gains->setSystemParameter("k", "2", "double", "", "", false)));
    add(*root, "SignalGain", "GainP");   // takes the name of a grouped component
    const auto ungrouped = root->ungroup(sub);
    ASSERT_TRUE(isOk(ungrouped.status()));
    const std::vector<std::string>& moved = *ungrouped;
    EXPECT_EQ(moved, (std::vector<std::string>{"GainI", "GainP_1"}));
    EXPECT_TRUE(root->parameters().find("k"));
    EXPECT_FALSE(root->component(sub));
}
