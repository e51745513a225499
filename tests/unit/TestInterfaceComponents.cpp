// The interface components: the boundary of a model that another program drives (an
// exported FMU). They compute nothing; what the outside writes into their nodes between
// steps is what the model sees.
#include "TestHelpers.h"

#include "core/NodeTypes.h"

#include <utility>

using namespace tlmhub;
using namespace tlmhub::test;

TEST(InterfaceComponents, EveryDomainHasACAndAQTypeWithOnePowerPort)
{
    const std::pair<const char*, NodeType> domains[] = {
        {"Hydraulic", NodeType::Hydraulic},   {"Mechanic", NodeType::Mechanic},
        {"MechanicRotational", NodeType::MechanicRotational}, {"Electric", NodeType::Electric},
        {"Pneumatic", NodeType::Pneumatic},   {"PetriNet", NodeType::PetriNet}};
    for (const auto& [domain, nodeType] : domains) {
        for (const auto& [suffix, kind] : {std::pair{"InterfaceC", CqsKind::C}, std::pair{"InterfaceQ", CqsKind::Q}}) {
            const std::string type = std::string(domain) + suffix;
            auto component = ComponentFactory::instance().create(type);
            ASSERT_TRUE(component) << type;
            EXPECT_EQ(component->kind(), kind) << type;
            ASSERT_EQ(component->ports().size(), 1u) << type;
            const Port* port = component->port("P1");
            ASSERT_TRUE(port) << type;
            EXPECT_EQ(port->kind(), PortKind::Power) << type;
            EXPECT_EQ(port->nodeType(), nodeType) << type;
        }
    }
}

TEST(InterfaceComponents, ValuesWrittenIntoTheInputReachTheOutputStepByStep)
{
    System root;
    add(root, "SignalInputInterface", "u");
    add(root, "SignalGain", "Gain");
    add(root, "SignalOutputInterface", "y");
    connectOk(root, "u", "out", "Gain", "in");
    connectOk(root, "Gain", "out", "y", "in");
    setParam(root, "Gain", "k#Value", "3");
    Result<Simulation> sim = compile(root, {0.0, 1.0, 0.1, 11});
    ASSERT_TRUE(sim) << describe(sim.status());
    ASSERT_TRUE(isOk(sim->initialise()));
    // Node storage is final once initialised: the outside holds these pointers from here on.
    double* u = root.component("u")->port("out")->node()->data() + NodeSignal::Value;
    const double* y = root.component("y")->port("in")->node()->data() + NodeSignal::Value;
    for (int step = 1; step <= 10; ++step) {
        *u = 0.5 * step;
        ASSERT_TRUE(isOk(sim->run(0.1 * step)));
        EXPECT_DOUBLE_EQ(*y, 1.5 * step) << "step " << step;
        EXPECT_DOUBLE_EQ(*u, 0.5 * step) << "the input interface must not overwrite its node";
    }
}

TEST(InterfaceComponents, AHydraulicCInterfaceLeavesTheWaveVariableToTheOutside)
{
    // A laminar orifice (Q-type) between a tank (C) and the interface (C): the flow through it
    // follows from the wave variables alone, so the outside's c and Zc decide it.
    System root;
    add(root, "HydraulicPressureSourceC", "Tank");
    add(root, "HydraulicLaminarOrifice", "Orifice");
    add(root, "HydraulicInterfaceC", "P1");
    connectOk(root, "Tank", "P1", "Orifice", "P1");
    connectOk(root, "Orifice", "P2", "P1", "P1");
    setParam(root, "Tank", "p#Value", "0");
    setParam(root, "Orifice", "Kc#Value", "1e-11");
    Result<Simulation> sim = compile(root, {0.0, 0.01, 0.001, 11});
    ASSERT_TRUE(sim) << describe(sim.status());
    ASSERT_TRUE(isOk(sim->initialise()));
    double* node = root.component("P1")->port("P1")->node()->data();
    node[NodeHydraulic::WaveVariable] = 2e6;
    node[NodeHydraulic::CharImpedance] = 1e9;
    ASSERT_TRUE(isOk(sim->run(0.005)));
    EXPECT_DOUBLE_EQ(node[NodeHydraulic::WaveVariable], 2e6);
    EXPECT_DOUBLE_EQ(node[NodeHydraulic::CharImpedance], 1e9);
    // Flow into the interface is negative (out of the port): from 2 MPa towards the 0 Pa tank.
    EXPECT_LT(node[NodeHydraulic::Flow], 0.0);
    EXPECT_GT(node[NodeHydraulic::Pressure], 0.0);
    EXPECT_LT(node[NodeHydraulic::Pressure], 2e6);
}
