// End stops of the C-type pistons (reference: hydraulic-lines-actuators.md, limitStroke and
// the end-stop quirk). A piston held beyond one of its stops by a mechanic Q-source gets, on
// top of the hydraulic force, CxLim = 0.5*NewCxLim in every step (no memory of the previous
// step) and ZxLim = 2*ZxLim0. The hydraulic part is isolated by an identical piston with
// use_sl = false under the same imposed motion: the difference of their P3 wave variables is
// CxLim, of their impedances ZxLim.
#include "TestHelpers.h"

#include "core/Results.h"

#include <cmath>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

std::vector<double> logged(System& s, const std::string& comp, const std::string& port,
                           const std::string& var)
{
    Port* p = s.component(comp)->port(port);
    return loggedData(*p, nodeVariableIndex(p->nodeType(), var), s.numLoggedSamples());
}

// A piston of `type` with both chambers plugged and its rod held at x, v with mass me.
void addHeldPiston(System& s, const std::string& type, const std::string& name, bool endStops,
                   double x, double v, double me)
{
    add(s, type, name);
    add(s, "HydraulicPlugQ", name + "Plug1");
    add(s, "HydraulicPlugQ", name + "Plug2");
    add(s, "MechanicTranslationalQSource", name + "Rod");
    connectOk(s, name, "P1", name + "Plug1", "P1");
    connectOk(s, name, "P2", name + "Plug2", "P1");
    connectOk(s, name, "P3", name + "Rod", "P1");
    setParam(s, name, "use_sl", endStops ? "true" : "false");
    setParam(s, name, "s_l#Value", "0.5");
    setParam(s, name + "Rod", "in_x#Value", std::to_string(x));
    setParam(s, name + "Rod", "in_v#Value", std::to_string(v));
    setParam(s, name + "Rod", "in_em#Value", std::to_string(me));
}

void checkEndStop(const std::string& type, double x, double v, double stopPosition)
{
    const double ts = 1e-3, me = 2.0;
    System s;
    addHeldPiston(s, type, "Limited", true, x, v, me);
    addHeldPiston(s, type, "Free", false, x, v, me);
    const std::size_t steps = 20;
    ASSERT_TRUE(run(s, 0, steps * ts, ts, steps + 1));

    const double zxLim0 = 0.1 * me / ts;
    const double zxLim = zxLim0 / (1.0 - 0.5);
    const double newCxLim = zxLim0 * (x - stopPosition) / ts + zxLim * v;
    const double cxLim = 0.5 * newCxLim;

    const auto cLimited = logged(s, "Limited", "P3", "WaveVariable");
    const auto cFree = logged(s, "Free", "P3", "WaveVariable");
    const auto zLimited = logged(s, "Limited", "P3", "CharImpedance");
    const auto zFree = logged(s, "Free", "P3", "CharImpedance");
    ASSERT_EQ(cLimited.size(), steps + 1);
    // Sample 0 is the start value; from the first step on the end stop acts. Tolerance: 1e-9
    // of CxLim (the difference of two forces of similar size).
    for (std::size_t i = 1; i < cLimited.size(); ++i) {
        EXPECT_NEAR(cLimited[i] - cFree[i], cxLim, 1e-9 * std::fabs(cxLim))
            << type << " x=" << x << " step " << i;
        EXPECT_NEAR(zLimited[i] - zFree[i], zxLim, 1e-9 * zxLim) << type << " x=" << x << " step " << i;
    }
}

} // namespace

TEST(PistonEndStops, CylinderBeyondTheOuterStopGetsHalfTheStopForceEveryStep)
{
    checkEndStop("HydraulicCylinderC", 0.01, 0.2, 0.0);
}

TEST(PistonEndStops, CylinderBeyondTheInnerStopGetsHalfTheStopForceEveryStep)
{
    checkEndStop("HydraulicCylinderC", -0.52, -0.3, -0.5);
}

TEST(PistonEndStops, SymmetricCylinderSharesTheEndStops)
{
    checkEndStop("HydraulicSymmetricCylinderC", 0.02, 0.1, 0.0);
    checkEndStop("HydraulicSymmetricCylinderC", -0.51, -0.1, -0.5);
}

TEST(PistonEndStops, SpringLoadedPistonBeyondEitherStopGetsHalfTheStopForceEveryStep)
{
    checkEndStop("HydraulicSpringLoadedPistonC", 0.01, 0.2, 0.0);
    checkEndStop("HydraulicSpringLoadedPistonC", -0.52, -0.3, -0.5);
}

TEST(PistonEndStops, InsideTheStrokeThereIsNoStopForce)
{
    const double ts = 1e-3;
    System s;
    addHeldPiston(s, "HydraulicCylinderC", "Limited", true, -0.25, 0.3, 2.0);
    addHeldPiston(s, "HydraulicCylinderC", "Free", false, -0.25, 0.3, 2.0);
    ASSERT_TRUE(run(s, 0, 10 * ts, ts, 11));
    const auto cLimited = logged(s, "Limited", "P3", "WaveVariable");
    const auto cFree = logged(s, "Free", "P3", "WaveVariable");
    const auto zLimited = logged(s, "Limited", "P3", "CharImpedance");
    const auto zFree = logged(s, "Free", "P3", "CharImpedance");
    for (std::size_t i = 0; i < cLimited.size(); ++i) {
        EXPECT_EQ(cLimited[i], cFree[i]) << "step " << i;
        EXPECT_EQ(zLimited[i], zFree[i]) << "step " << i;
    }
}
