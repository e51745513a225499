// Electric sources and sensor completing Hopsan's default library (issue 21):
// ElectricCSource, ElectricQSource and ElectricNodeSensor, checked in small circuits
// against Ohm's law and the TLM boundary relation u = c + Zc * i.
#include "TestHelpers.h"

#include "core/Results.h"

#include <cmath>

using namespace tlmhub;
using namespace tlmhub::test;

namespace lcelectric {

double lastLogged(System& s, const std::string& comp, const std::string& port)
{
    Port* p = s.component(comp)->port(port);
    const auto v = loggedData(*p, NodeSignal::Value, s.numLoggedSamples());
    EXPECT_FALSE(v.empty());
    for (double x : v) EXPECT_TRUE(std::isfinite(x)) << comp << "." << port;
    return v.empty() ? NAN : v.back();
}

} // namespace lcelectric

using namespace lcelectric;

TEST(LibraryCompletionElectricCSource, DrivesAResistorThroughItsImpedance)
{
    // Source (c, Zc) -- resistor G -- ground: i = G c / (1 + G Zc), node voltage u = c - Zc i.
    // With Zc = 0 the source holds its voltage exactly. Tolerance 1e-12 relative.
    for (double zc : {0.0, 2.0}) {
        System s;
        add(s, "ElectricCSource", "Source");
        add(s, "ElectricResistor", "R");
        add(s, "ElectricGround", "Ground");
        add(s, "ElectricNodeSensor", "Sensor");
        connectOk(s, "Source", "P1", "R", "Pel1");
        connectOk(s, "R", "Pel2", "Ground", "Pel1");
        connectOk(s, "Sensor", "P1", "Source", "P1");
        setParam(s, "Source", "in_c#Value", "12");
        setParam(s, "Source", "in_z#Value", std::to_string(zc));
        setParam(s, "R", "Conduct#Value", "0.1");
        ASSERT_TRUE(run(s, 0, 0.1, 1e-3, 11));
        const double i = 0.1 * 12.0 / (1.0 + 0.1 * zc);
        EXPECT_NEAR(lastLogged(s, "Sensor", "u"), 12.0 - zc * i, 1e-12 * 12.0) << "Zc=" << zc;
        EXPECT_NEAR(std::fabs(lastLogged(s, "Sensor", "i")), i, 1e-12 * i) << "Zc=" << zc;
        EXPECT_NEAR(lastLogged(s, "Sensor", "c"), 12.0, 1e-12) << "Zc=" << zc;
        EXPECT_NEAR(lastLogged(s, "Sensor", "Zc"), zc, 1e-12) << "Zc=" << zc;
    }
}

TEST(LibraryCompletionElectricQSource, ImposesVoltageAndCurrentAndTheSensorReadsAllFourSlots)
{
    // Q source against a C source: the node holds the Q side's u and i and the C side's c, Zc.
    System s;
    add(s, "ElectricQSource", "Q");
    add(s, "ElectricCSource", "C");
    add(s, "ElectricNodeSensor", "Sensor");
    connectOk(s, "Q", "P1", "C", "P1");
    connectOk(s, "Sensor", "P1", "Q", "P1");
    setParam(s, "Q", "in_u#Value", "5");
    setParam(s, "Q", "in_i#Value", "0.3");
    setParam(s, "C", "in_c#Value", "1");
    setParam(s, "C", "in_z#Value", "2");
    ASSERT_TRUE(run(s, 0, 0.1, 1e-3, 11));
    EXPECT_DOUBLE_EQ(lastLogged(s, "Sensor", "u"), 5.0);
    EXPECT_DOUBLE_EQ(lastLogged(s, "Sensor", "i"), 0.3);
    EXPECT_DOUBLE_EQ(lastLogged(s, "Sensor", "c"), 1.0);
    EXPECT_DOUBLE_EQ(lastLogged(s, "Sensor", "Zc"), 2.0);
}

TEST(LibraryCompletionElectricQSource, FollowsAVaryingInputIntoACapacitor)
{
    // A sine current into a capacitor (then a resistor to ground) through the Q source: runs to its stop time with finite
    // values; the node current is the input at every logged step, and the sensor (a signal
    // component, stepped before the Q side) reports it one step later.
    System s;
    add(s, "SignalSineWave", "Wave");
    add(s, "ElectricQSource", "Q");
    add(s, "ElectricCapacitance2", "Cap");
    add(s, "ElectricResistor", "R");
    add(s, "ElectricGround", "Ground");
    add(s, "ElectricNodeSensor", "Sensor");
    connectOk(s, "Wave", "out", "Q", "in_i");
    connectOk(s, "Q", "P1", "Cap", "Pel1");
    connectOk(s, "Cap", "Pel2", "R", "Pel1");
    connectOk(s, "R", "Pel2", "Ground", "Pel1");
    connectOk(s, "Sensor", "P1", "Q", "P1");
    ASSERT_TRUE(run(s, 0, 1, 1e-4, 101));
    Port* in = s.component("Q")->port("in_i");
    const auto input = loggedData(*in, NodeSignal::Value, s.numLoggedSamples());
    Port* node = s.component("Q")->port("P1");
    const auto current = loggedData(*node, NodeElectric::Current, s.numLoggedSamples());
    ASSERT_EQ(input.size(), current.size());
    for (std::size_t k = 1; k < input.size(); ++k) EXPECT_DOUBLE_EQ(current[k], input[k]);
    EXPECT_NEAR(lastLogged(s, "Sensor", "i"), std::sin(2.0 * 3.14159265358979323846 * (1.0 - 1e-4)), 1e-12);
}

TEST(LibraryCompletionElectricNodeSensor, UnconnectedReadsTheStartValues)
{
    System s;
    add(s, "ElectricNodeSensor", "Sensor");
    setParam(s, "Sensor", "P1#Voltage", "3");
    ASSERT_TRUE(run(s, 0, 0.01, 1e-3, 11));
    EXPECT_DOUBLE_EQ(lastLogged(s, "Sensor", "u"), 3.0);
}
