// Analytic checks independent of Hopsan's data: each builds a small model through the core
// API and compares with a closed-form solution; the tolerance is stated with each check.
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

} // namespace

TEST(Analytic, LaminarOrificeFlowIsProportionalToPressureDrop)
{
    // Between two ideal pressure sources (Zc = 0): q = Kc * (p1 - p2). Tolerance 1e-12 relative.
    for (double p1 : {2e6, 1e7, 3e7}) {
        System s;
        add(s, "HydraulicPressureSourceC", "High");
        add(s, "HydraulicLaminarOrifice", "Orifice");
        add(s, "HydraulicPressureSourceC", "Low");
        connectOk(s, "High", "P1", "Orifice", "P1");
        connectOk(s, "Orifice", "P2", "Low", "P1");
        setParam(s, "High", "p#Value", std::to_string(p1));
        setParam(s, "Low", "p#Value", "1e6");
        setParam(s, "Orifice", "Kc#Value", "2e-11");
        ASSERT_TRUE(run(s, 0, 0.01, 1e-3, 11));
        const double q = logged(s, "Orifice", "P2", "Flow").back();
        const double expected = 2e-11 * (p1 - 1e6);
        EXPECT_NEAR(q, expected, 1e-12 * std::fabs(expected)) << "p1=" << p1;
        EXPECT_NEAR(logged(s, "Orifice", "P1", "Flow").back(), -expected, 1e-12 * std::fabs(expected));
    }
}

TEST(Analytic, VolumePressureBuildUpFollowsBulkModulus)
{
    // A constant flow q into a closed volume V: dp/dt = Beta_e * q / V.
    // Tolerance: 0.5 % of the pressure rise after the first 10 ms (TLM wave start-up).
    System s;
    add(s, "HydraulicFlowSourceQ", "Pump");
    add(s, "HydraulicVolume", "Volume");
    add(s, "HydraulicPlugQ", "Plug");
    connectOk(s, "Pump", "P1", "Volume", "P1");
    connectOk(s, "Volume", "P2", "Plug", "P1");
    setParam(s, "Pump", "q#Value", "1e-5");
    setParam(s, "Volume", "V", "1e-3");
    setParam(s, "Volume", "Beta_e", "1e9");
    ASSERT_TRUE(run(s, 0, 0.1, 1e-5, 101));
    const auto p = logged(s, "Volume", "P2", "Pressure");
    const auto& t = s.logTime();
    const double rate = 1e9 * 1e-5 / 1e-3;   // Pa/s
    for (std::size_t i = 10; i < p.size(); ++i) {
        const double expected = 1e5 + rate * t[i];
        EXPECT_NEAR(p[i], expected, 0.005 * rate * t[i]) << "t=" << t[i];
    }
}

TEST(Analytic, MassSpringOscillatesAtItsNaturalFrequency)
{
    // Mass m on a spring k (no damping): period 2*pi*sqrt(m/k). Tolerance 0.5 %.
    System s;
    add(s, "MechanicFixedPosition", "Wall");
    add(s, "MechanicTranslationalSpring", "Spring");
    add(s, "MechanicTranslationalMass", "Mass");
    add(s, "MechanicForceTransformer", "Force");
    connectOk(s, "Wall", "Pm1", "Spring", "P1");
    connectOk(s, "Spring", "P2", "Mass", "P1");
    connectOk(s, "Mass", "P2", "Force", "P1");
    setParam(s, "Spring", "k#Value", "1e4");
    setParam(s, "Mass", "m", "1");
    setParam(s, "Mass", "B#Value", "0");
    setParam(s, "Force", "F#Value", "100");
    ASSERT_TRUE(run(s, 0, 0.5, 1e-5, 50001));
    const auto v = logged(s, "Mass", "P2", "Velocity");
    const auto& t = s.logTime();
    std::vector<double> upCrossings;
    for (std::size_t i = 1; i < v.size(); ++i)
        if (v[i - 1] < 0.0 && v[i] >= 0.0)
            upCrossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-v[i - 1]) / (v[i] - v[i - 1]));
    ASSERT_GE(upCrossings.size(), 4u);
    const double period = (upCrossings.back() - upCrossings.front()) / (upCrossings.size() - 1);
    const double expected = 2.0 * M_PI * std::sqrt(1.0 / 1e4);
    EXPECT_NEAR(period, expected, 0.005 * expected);
}

TEST(Analytic, LosslessLineDelaysAWaveByItsTimeDelay)
{
    // A pressure step at one end of a lossless line reaches the closed end after deltat.
    // Tolerance: one time step.
    System s;
    add(s, "SignalStep", "Step");
    add(s, "HydraulicPressureSourceQ", "Source");
    add(s, "HydraulicTLMlossless", "Line");
    add(s, "HydraulicPlugQ", "Plug");
    connectOk(s, "Step", "out", "Source", "p");
    connectOk(s, "Source", "P1", "Line", "P1");
    connectOk(s, "Line", "P2", "Plug", "P1");
    setParam(s, "Step", "y_0#Value", "1e5");
    setParam(s, "Step", "y_A#Value", "1e6");
    setParam(s, "Step", "t_step#Value", "0.005");
    setParam(s, "Line", "deltat", "0.01");
    const double Ts = 1e-4;
    ASSERT_TRUE(run(s, 0, 0.05, Ts, 501));
    const auto p1 = logged(s, "Line", "P1", "Pressure");
    const auto p2 = logged(s, "Line", "P2", "Pressure");
    const auto& t = s.logTime();
    auto firstAbove = [&](const std::vector<double>& p) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if (p[i] > 5e5) return t[i];
        return -1.0;
    };
    const double sent = firstAbove(p1), arrived = firstAbove(p2);
    ASSERT_GT(sent, 0.0);
    ASSERT_GT(arrived, 0.0);
    EXPECT_NEAR(arrived - sent, 0.01, Ts * 1.01);
}

TEST(Analytic, FirstOrderLowPassStepResponse)
{
    // y = 1 - exp(-wc t) for a unit step. Tolerance 1e-5 absolute (Tustin, wc*h = 1e-3).
    System s;
    add(s, "SignalConstant", "One");
    add(s, "SignalLP1Filter", "Filter");
    add(s, "SignalSink", "Scope");
    connectOk(s, "One", "y", "Filter", "in");
    connectOk(s, "Filter", "out", "Scope", "in");
    setParam(s, "One", "y#Value", "1");
    setParam(s, "Filter", "omega", "10");
    ASSERT_TRUE(run(s, 0, 1.0, 1e-4, 101));
    const auto y = logged(s, "Filter", "out", "Value");
    const auto& t = s.logTime();
    for (std::size_t i = 1; i < y.size(); ++i)
        EXPECT_NEAR(y[i], 1.0 - std::exp(-10.0 * t[i]), 1e-5) << "t=" << t[i];
}

TEST(Analytic, IntegratorOfAConstantIsARamp)
{
    // The trapezoidal integral of a constant c is exactly c*t. Tolerance 1e-12 relative.
    System s;
    add(s, "SignalConstant", "C");
    add(s, "SignalIntegrator2", "Integrator");
    add(s, "SignalSink", "Scope");
    connectOk(s, "C", "y", "Integrator", "in");
    connectOk(s, "Integrator", "out", "Scope", "in");
    setParam(s, "C", "y#Value", "2.5");
    ASSERT_TRUE(run(s, 0, 2.0, 1e-3, 201));
    const auto y = logged(s, "Integrator", "out", "Value");
    const auto& t = s.logTime();
    for (std::size_t i = 0; i < y.size(); ++i) EXPECT_NEAR(y[i], 2.5 * t[i], 1e-12 * (1.0 + 2.5 * t[i]));
}
