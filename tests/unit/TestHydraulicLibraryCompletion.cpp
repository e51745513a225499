// Hydraulic types added to complete Hopsan's default library (issue 21): for each type a
// limiting case with a closed-form answer, built through the core API between ideal
// pressure sources (Zc = 0) so the port pressures are the source pressures.
#include "TestHelpers.h"

#include "core/Results.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

using namespace tlmhub;
using namespace tlmhub::test;

namespace hydcompletion {

std::vector<double> series(System& s, const std::string& comp, const std::string& port, const std::string& var)
{
    Port* p = s.component(comp)->port(port);
    return loggedData(*p, nodeVariableIndex(p->nodeType(), var), s.numLoggedSamples());
}

double last(System& s, const std::string& comp, const std::string& port, const std::string& var)
{
    return series(s, comp, port, var).back();
}

// Adds an ideal pressure source `name` at pressure p and connects it to comp.port.
void source(System& s, const std::string& name, double p, const std::string& comp, const std::string& port)
{
    add(s, "HydraulicPressureSourceC", name);
    setParam(s, name, "p#Value", std::to_string(p));
    connectOk(s, name, "P1", comp, port);
}

bool allFinite(System& s, const std::string& comp, const std::vector<std::string>& ports, const std::string& var)
{
    for (const auto& port : ports)
        for (double v : series(s, comp, port, var))
            if (!std::isfinite(v)) return false;
    return true;
}

constexpr double kRho = 890.0;

// Orifice law q = Cq * A * sqrt(2 dp / rho).
double orificeFlow(double Cq, double area, double dp)
{
    return Cq * area * std::sqrt(2.0 * dp / kRho);
}

} // namespace hydcompletion

using namespace hydcompletion;

TEST(HydraulicLibraryCompletion, PoppetValveStaysClosedBelowCrackingAndFollowsOrificeLawAbove)
{
    // d_1 = d_2 (no annulus): the poppet sits where A*(pN - pC) = F_0 + k*x. Below the
    // cracking pressure F_0/A it stays shut (q = 0 exactly); above, the seat flow follows
    // q = Cq*pi*d_1*x*sqrt(2*dp/rho). Tolerance 1 % on x and q.
    const double d = 0.01, A = pi * d * d / 4.0, F0 = 100.0, k = 1e5, pC = 1e5, pS = 1e5;
    for (double pN : {1.0e6, 5.0e6}) {
        System s;
        add(s, "Hydraulic22PoppetValve", "Valve");
        source(s, "N", pN, "Valve", "PN");
        source(s, "S", pS, "Valve", "PS");
        source(s, "C", pC, "Valve", "PC");
        setParam(s, "Valve", "k#Value", "1e5");
        setParam(s, "Valve", "d_d", "0.5e-3");
        ASSERT_TRUE(run(s, 0, 1.0, 1e-4, 101));
        const double x = last(s, "Valve", "xv_out", "Value");
        const double q = last(s, "Valve", "PS", "Flow"); // positive: flow leaves at PS
        const double xExpected = std::max((A * (pN - pC) - F0) / k, 0.0);
        if (xExpected == 0.0) {
            EXPECT_EQ(x, 0.0) << "pN=" << pN;
            EXPECT_EQ(q, 0.0) << "pN=" << pN;
        } else {
            EXPECT_NEAR(x, xExpected, 0.01 * xExpected);
            const double qExpected = orificeFlow(0.67, pi * d * xExpected, pN - pS);
            EXPECT_NEAR(q, qExpected, 0.01 * qExpected);
        }
        EXPECT_TRUE(allFinite(s, "Valve", {"PN", "PS", "PC"}, "Pressure"));
    }
}
