// The TLM co-simulation interfaces completing Hopsan's Connectivity library (issue 21):
// <Domain>InterfaceTLM writes c = e2 + Zc * f2 from the received effort e2 and flow f2,
// delayed by Td (interpolated between samples unless Td is one step).
#include "TestHelpers.h"

#include "core/Results.h"

#include <cmath>
#include <sstream>

using namespace tlmhub;
using namespace tlmhub::test;

namespace lcconnectivity {

struct Domain {
    std::string prefix;   // type name without "InterfaceTLM"
    std::string flow, effort;
};

const Domain kDomains[] = {
    {"Hydraulic", "q2", "p2"},
    {"Mechanic", "v2", "f2"},
    {"MechanicRotational", "w2", "t2"},
    {"Electric", "i2", "u2"},
    {"Pneumatic", "e2", "p2"},
};

} // namespace lcconnectivity

using namespace lcconnectivity;

TEST(LibraryCompletionInterfaceTLM, ConstantInputsGiveTheWaveOfTheReceivedEnd)
{
    // Td = one step: c = e2 + Zc * f2 and the node's Zc = Zc after the first step. Exact.
    for (const Domain& d : kDomains) {
        System s;
        const std::string type = d.prefix + "InterfaceTLM";
        add(s, type, "Tlm");
        add(s, d.prefix + "InterfaceQ", "Other");   // a Q side with no equations of its own
        connectOk(s, "Tlm", "P1", "Other", "P1");
        EXPECT_EQ(s.component("Tlm")->kind(), CqsKind::C) << type;
        setParam(s, "Tlm", d.effort + "#Value", "5");
        setParam(s, "Tlm", d.flow + "#Value", "7");
        setParam(s, "Tlm", "Zc", "3");
        setParam(s, "Tlm", "Td", "0.001");
        ASSERT_TRUE(run(s, 0, 0.1, 1e-3, 11)) << type;
        const auto c = loggedSlot(s, "Tlm", "P1", "WaveVariable");
        const auto zc = loggedSlot(s, "Tlm", "P1", "CharImpedance");
        ASSERT_EQ(c.size(), 11u) << type;
        for (std::size_t k = 1; k < c.size(); ++k) {
            EXPECT_DOUBLE_EQ(c[k], 5.0 + 3.0 * 7.0) << type << " sample " << k;
            EXPECT_DOUBLE_EQ(zc[k], 3.0) << type << " sample " << k;
        }
    }
}

TEST(LibraryCompletionInterfaceTLM, DelaysASampledRampByTd)
{
    // e2 = t (a new sample every step), f2 = 0.5, Zc = 2, Td = 2.5 steps: once the history
    // holds ramp samples, both interpolations reproduce the ramp, c = (t - Td) + 1. 1e-9.
    for (int method : {0, 1}) {
        System s;
        add(s, "SignalTime", "Clock");
        add(s, "HydraulicInterfaceTLM", "Tlm");
        add(s, "HydraulicInterfaceQ", "Other");
        connectOk(s, "Clock", "out", "Tlm", "p2");
        connectOk(s, "Tlm", "P1", "Other", "P1");
        setParam(s, "Tlm", "q2#Value", "0.5");
        setParam(s, "Tlm", "Zc", "2");
        setParam(s, "Tlm", "Td", "0.0025");
        setParam(s, "Tlm", "interpolation", std::to_string(method));
        ASSERT_TRUE(run(s, 0, 0.1, 1e-3, 101));
        const auto c = loggedSlot(s, "Tlm", "P1", "WaveVariable");
        const auto& t = s.logTime();
        for (std::size_t k = 5; k < c.size(); ++k)
            EXPECT_NEAR(c[k], (t[k] - 0.0025) + 1.0, 1e-9) << "method " << method << " t=" << t[k];
    }
}

TEST(LibraryCompletionInterfaceTLM, FeedsAnOrificeLikeAPressureSourceBehindAnImpedance)
{
    // Received p2 = 2 MPa, q2 = 0.1 l/s, Zc = 1e9: c = 2.1 MPa. Through a laminar orifice Kc
    // to a 1 MPa source: q = Kc (c - 1e6) / (1 + Kc Zc). Tolerance 1e-9 relative.
    System s;
    add(s, "HydraulicInterfaceTLM", "Tlm");
    add(s, "HydraulicLaminarOrifice", "Orifice");
    add(s, "HydraulicPressureSourceC", "Tank");
    connectOk(s, "Tlm", "P1", "Orifice", "P1");
    connectOk(s, "Orifice", "P2", "Tank", "P1");
    setParam(s, "Tlm", "p2#Value", "2e6");
    setParam(s, "Tlm", "q2#Value", "1e-4");
    setParam(s, "Tlm", "Zc", "1e9");
    setParam(s, "Tlm", "Td", "0.001");
    setParam(s, "Tank", "p#Value", "1e6");
    setParam(s, "Orifice", "Kc#Value", "1e-11");
    ASSERT_TRUE(run(s, 0, 1, 1e-3, 101));
    const double q = 1e-11 * (2.1e6 - 1e6) / (1.0 + 1e-11 * 1e9);
    const auto flow = loggedSlot(s, "Orifice", "P2", "Flow");
    const auto pressure = loggedSlot(s, "Orifice", "P1", "Pressure");
    for (double v : pressure) EXPECT_TRUE(std::isfinite(v));
    EXPECT_NEAR(flow.back(), q, 1e-9 * q);
    // The interface end's pressure: p = c + Zc q_in, q_in = -q (the orifice draws from it).
    EXPECT_NEAR(pressure.back(), 2.1e6 - 1e9 * q, 1e-9 * 2.1e6);
}
