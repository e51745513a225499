// Multiport initial values: a component may write an initial value into each sub-port
// node while initialising, overriding the start values the connected C components loaded.
// MechanicCylinderBlockWithSwashPlate does so for its pistons (Hopsan does the same), which
// is what makes the In-Line Axial Piston Machine reference set pass.
#include "TestHelpers.h"

#include "core/NodeTypes.h"

#include <cmath>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

double nodeValue(System& s, const std::string& comp, const std::string& port, int id)
{
    Port* p = s.component(comp)->port(port);
    return p->node()->data()[id];
}

// Two pistons between a cylinder block and a valve plate; piston A starts at x = 0.05.
void buildPump(System& s)
{
    add(s, "MechanicCylinderBlockWithSwashPlate", "Block");
    add(s, "MechanicMotor", "Motor");
    add(s, "HydraulicPumpPiston", "A");
    add(s, "HydraulicPumpPiston", "B");
    add(s, "HydraulicValvePlate", "Plate");
    add(s, "HydraulicMultiTankC", "TankA");
    add(s, "HydraulicMultiTankC", "TankB");
    connectOk(s, "A", "P3", "Block", "P1");
    connectOk(s, "B", "P3", "Block", "P1");
    connectOk(s, "Motor", "P1", "Block", "P2");
    connectOk(s, "A", "P1", "Plate", "P1");
    connectOk(s, "B", "P1", "Plate", "P1");
    connectOk(s, "Plate", "PA", "TankA", "MP");
    connectOk(s, "Plate", "PB", "TankB", "MP");
    setParam(s, "A", "P3#Position", "0.05");
    setParam(s, "A", "P3#Velocity", "0.3");
    setParam(s, "Block", "angle#Value", "0.2");
    setParam(s, "Block", "r#Value", "0.04");
    setParam(s, "Block", "theta_offset#Value", "0.5");
}

} // namespace

TEST(MultiPortInitialValues, CylinderBlockZeroesItsPistonNodesOverridingStartValues)
{
    System s;
    buildPump(s);
    Result<Simulation> sim = compile(s, {.startTime = 0.0, .stopTime = 1e-3, .timestep = 1e-5, .logSamples = 2});
    ASSERT_TRUE(isOk(sim.status()));
    ASSERT_TRUE(isOk(sim->initialise()));

    // Piston A loaded x = 0.05, v = 0.3 as start values; the block's initialise zeroed them
    // and set the equivalent mass the pistons use for their minimum volume.
    EXPECT_EQ(nodeValue(s, "A", "P3", NodeMechanic::Position), 0.0);
    EXPECT_EQ(nodeValue(s, "A", "P3", NodeMechanic::Velocity), 0.0);
    EXPECT_EQ(nodeValue(s, "A", "P3", NodeMechanic::EquivalentMass), 0.02);
    EXPECT_EQ(nodeValue(s, "B", "P3", NodeMechanic::EquivalentMass), 0.02);

    // So the stroke is centred on x = 0: after one step piston k sits at
    // 0 + r*tan(angle)*sin(-theta_offset - 2*pi*k/N), the block still at angle 0
    // (with the start value kept, piston A would sit 0.05 further out).
    ASSERT_TRUE(isOk(sim->runSteps(1)));
    const double stroke = 0.04 * std::tan(0.2);
    const double pi = 3.141592653589793;
    EXPECT_NEAR(nodeValue(s, "A", "P3", NodeMechanic::Position), stroke * std::sin(-0.5), 1e-15);
    EXPECT_NEAR(nodeValue(s, "B", "P3", NodeMechanic::Position), stroke * std::sin(-0.5 - pi), 1e-15);
}
