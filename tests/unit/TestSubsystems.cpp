// Subsystems (core.md §2.7, §3.3, §3.5): system ports are pass-throughs to one shared node,
// the subsystem's kind follows what is connected inside, and a subsystem may run with a
// shorter time step of its own.
#include "TestHelpers.h"

#include "core/Results.h"
#include "core/hmf/HmfLoader.h"
#include "core/hmf/HmfSaver.h"
#include "core/hmf/PreservedXml.h"

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

System& addSubsystem(System& parent, const std::string& name)
{
    auto sub = std::make_unique<System>();
    sub->setNameRaw(name);
    System* raw = sub.get();
    parent.addComponent(std::move(sub));
    return *raw;
}

// Constant C -> Sub.in -> Gain G (k = 2) -> Sub.out -> Sink.
System& gainInSubsystem(System& root)
{
    add(root, "SignalConstant", "C");
    add(root, "SignalSink", "Sink");
    System& sub = addSubsystem(root, "Sub");
    sub.addSystemPort("in");
    sub.addSystemPort("out");
    add(sub, "SignalGain", "G");
    connectOk(sub, "in", "in", "G", "in");
    connectOk(sub, "G", "out", "out", "out");
    connectOk(root, "C", "y", "Sub", "in");
    connectOk(root, "Sub", "out", "Sink", "in");
    setParam(root, "C", "y#Value", "3");
    sub.component("G")->parameters().find("k#Value")->value = "2";
    return sub;
}

} // namespace

TEST(Subsystems, SystemPortsPassSignalsThroughOneNode)
{
    System root;
    System& sub = gainInSubsystem(root);
    EXPECT_EQ(sub.kind(), CqsKind::S);
    // Outside and inside ports share the node: no copies.
    EXPECT_EQ(root.component("C")->port("y")->node(), sub.component("G")->port("in")->node());
    ASSERT_TRUE(run(root, 0, 0.01, 0.001, 11));
    EXPECT_DOUBLE_EQ(sub.component("G")->port("out")->node()->value(0), 6.0);
    // The crossing node is logged by the outer system under both names.
    const Result<VariableRef> variable = resolveVariable(root, "Sub$G#out#Value");
    ASSERT_TRUE(variable) << variable.status().message();
    EXPECT_EQ(loggedData(*variable->port, variable->slot, root.numLoggedSamples()).back(), 6.0);
}

TEST(Subsystems, KindFollowsInsideConnectionsAndTLMRulesHoldAcrossPorts)
{
    System root;
    System& sub = addSubsystem(root, "Sub");
    sub.addSystemPort("P");
    add(sub, "HydraulicVolume", "V");
    add(sub, "HydraulicPlugQ", "Plug");
    connectOk(sub, "V", "P2", "Plug", "P1");
    connectOk(sub, "V", "P1", "P", "P");
    EXPECT_EQ(sub.kind(), CqsKind::C);
    // A C-type subsystem carries start values for its power port.
    EXPECT_NE(sub.parameters().find("P#Pressure"), nullptr);
    add(root, "HydraulicVolume", "Outside");
    const Status refused = root.connect("Outside", "P1", "Sub", "P");
    EXPECT_EQ(refused.code(), StatusCode::IllegalConnection);
    EXPECT_NE(refused.message().find("two C-type"), std::string::npos) << refused.message();
    ASSERT_TRUE(isOk(root.removeComponent("Outside")));
    add(root, "HydraulicFlowSourceQ", "Pump");
    connectOk(root, "Pump", "P1", "Sub", "P");
    setParam(root, "Pump", "q#Value", "1e-5");
    ASSERT_TRUE(run(root, 0, 0.1, 1e-4, 11));
    // The pump fills the inner volume: pressure rises by about Beta*q*t/V = 1e6 Pa.
    const double p = sub.component("V")->port("P2")->node()->value(NodeHydraulic::Pressure);
    EXPECT_NEAR(p, 1e5 + 1e9 * 1e-5 * 0.1 / 1e-3, 0.02e6);
}

TEST(Subsystems, OwnShorterTimeStepRunsSeveralStepsPerParentStep)
{
    System root;
    System& sub = addSubsystem(root, "Fast");
    sub.inheritTimestep = false;
    sub.desiredTimestep = 0.00025;   // four sub-steps per parent step of 1 ms
    add(sub, "SignalTime", "Clock");
    add(sub, "SignalSink", "Sink");
    connectOk(sub, "Clock", "out", "Sink", "in");
    add(root, "SignalTime", "Clock");
    add(root, "SignalSink", "Sink");
    connectOk(root, "Clock", "out", "Sink", "in");
    ASSERT_TRUE(run(root, 0, 0.01, 0.001, 41));
    EXPECT_EQ(root.takenSteps(), 10u);
    EXPECT_EQ(sub.takenSteps(), 40u);
    // The subsystem logs its own nodes against its own time vector, with its own steps.
    ASSERT_EQ(sub.numLoggedSamples(), 41u);
    EXPECT_NEAR(sub.logTime()[1], 0.00025, 1e-15);
    const auto y = loggedData(*sub.component("Clock")->port("out"), 0, sub.numLoggedSamples());
    EXPECT_EQ(y, sub.logTime());
    EXPECT_EQ(root.numLoggedSamples(), 11u);   // limited to the parent's steps + 1
}

TEST(Subsystems, ConditionalSubsystemFreezesWhileOff)
{
    System root;
    auto cond = std::make_unique<System>();
    cond->setNameRaw("Cond");
    cond->makeConditional();
    System* sub = cond.get();
    root.addComponent(std::move(cond));
    add(*sub, "SignalConstant", "One");
    add(*sub, "SignalIntegrator2", "Integrator");
    add(*sub, "SignalSink", "Sink");
    connectOk(*sub, "One", "y", "Integrator", "in");
    connectOk(*sub, "Integrator", "out", "Sink", "in");
    // `on` is unconnected and 0: the integrator must not move.
    ASSERT_TRUE(run(root, 0, 0.1, 0.001, 11));
    EXPECT_EQ(sub->component("Integrator")->port("out")->node()->value(0), 0.0);
    sub->parameters().find("on#Value")->value = "1";
    ASSERT_TRUE(run(root, 0, 0.1, 0.001, 11));
    EXPECT_NEAR(sub->component("Integrator")->port("out")->node()->value(0), 0.1, 1e-12);
}

// Ungrouping and the editor rename system ports: the connections on both sides stay.
TEST(Subsystems, RenamingASystemPortKeepsItsConnectionsInsideAndOut)
{
    System root;
    System& sub = gainInSubsystem(root);
    const Result<std::string> renamed = sub.renameSystemPort("in", "input signal");
    ASSERT_TRUE(renamed) << renamed.status().message();
    EXPECT_EQ(*renamed, "input_signal");
    EXPECT_EQ(sub.systemPort("in"), nullptr);
    ASSERT_NE(sub.systemPort("input_signal"), nullptr);
    EXPECT_EQ(root.component("C")->port("y")->node(), sub.component("G")->port("in")->node());
    // A taken name gets a suffix; an unknown port is not_found.
    EXPECT_EQ(*sub.renameSystemPort("input_signal", "G"), "G_1");
    EXPECT_EQ(sub.renameSystemPort("nothing", "x").status().code(), StatusCode::NotFound);
    ASSERT_TRUE(run(root, 0, 0.01, 0.001, 11));
    EXPECT_DOUBLE_EQ(sub.component("G")->port("out")->node()->value(0), 6.0);
}

// The drawn layout of a system port: its pose, its place on the subsystem's icon and the
// lines of its connections inside and outside.
void drawSystemPortIn(System& root, System& sub)
{
    using preserved::connectionKey;
    sub.systemPortExtras["in"].layout.pose = {10.0, 20.0, 90.0, false};
    sub.layout.iconPorts = {{.name = "in", .x = 0.0, .y = 0.5}, {.name = "out", .x = 1.0, .y = 0.5}};
    sub.connectionExtras[connectionKey("in", "in", "G", "in")].layout.points = {{10, 20}, {30, 20}};
    root.connectionExtras[connectionKey("C", "y", "Sub", "in")].layout.points = {{0, 0}, {5, 0}};
}

TEST(Subsystems, ARenamedSystemPortKeepsItsLayoutThroughSaveAndLoad)
{
    System root;
    System& sub = gainInSubsystem(root);
    drawSystemPortIn(root, sub);
    ASSERT_EQ(*sub.renameSystemPort("in", "u"), "u");

    const LoadedModel reloaded = loadHmfString(saveHmfString(root), "");
    ASSERT_TRUE(reloaded.root) << reloaded.firstError();
    const auto* loadedSub = dynamic_cast<const System*>(reloaded.root->component("Sub"));
    ASSERT_NE(loadedSub, nullptr);
    ASSERT_TRUE(loadedSub->systemPortExtras.count("u"));
    EXPECT_EQ(loadedSub->systemPortExtras.at("u").layout.pose, (Pose{10.0, 20.0, 90.0, false}));
    ASSERT_EQ(loadedSub->layout.iconPorts.size(), 2u);
    EXPECT_EQ(loadedSub->layout.iconPorts[0].name, "u");
    using preserved::connectionKey;
    ASSERT_TRUE(loadedSub->connectionExtras.count(connectionKey("u", "u", "G", "in")));
    EXPECT_EQ(loadedSub->connectionExtras.at(connectionKey("u", "u", "G", "in")).layout.points,
              (std::vector<LinePoint>{{10, 20}, {30, 20}}));
    ASSERT_TRUE(reloaded.root->connectionExtras.count(connectionKey("C", "y", "Sub", "u")));
    EXPECT_EQ(reloaded.root->connectionExtras.at(connectionKey("C", "y", "Sub", "u")).layout.points,
              (std::vector<LinePoint>{{0, 0}, {5, 0}}));
}

TEST(Subsystems, ADeletedSystemPortLeavesNoLayoutBehind)
{
    System root;
    System& sub = gainInSubsystem(root);
    drawSystemPortIn(root, sub);
    ASSERT_TRUE(isOk(sub.deleteSystemPort("in")));
    EXPECT_FALSE(sub.systemPortExtras.count("in"));
    ASSERT_EQ(sub.layout.iconPorts.size(), 1u);
    EXPECT_EQ(sub.layout.iconPorts[0].name, "out");
    // A new port of the same name, connected again, starts without the old lines.
    sub.addSystemPort("in");
    connectOk(sub, "in", "in", "G", "in");
    connectOk(root, "C", "y", "Sub", "in");
    EXPECT_TRUE(sub.connectionExtras.empty());
    EXPECT_TRUE(root.connectionExtras.empty());
}

TEST(Subsystems, DeletingASystemPortDisconnectsItInsideAndOut)
{
    System root;
    System& sub = gainInSubsystem(root);
    ASSERT_TRUE(isOk(sub.deleteSystemPort("in")));
    EXPECT_EQ(sub.systemPort("in"), nullptr);
    EXPECT_FALSE(root.component("C")->port("y")->isConnected());
    EXPECT_FALSE(sub.component("G")->port("in")->isConnected());
    EXPECT_NE(root.component("C")->port("y")->node(), sub.component("G")->port("in")->node());
    EXPECT_TRUE(sub.component("G")->port("out")->isConnected()) << "the other port's connections stay";
    EXPECT_EQ(sub.deleteSystemPort("in").code(), StatusCode::NotFound);
}
