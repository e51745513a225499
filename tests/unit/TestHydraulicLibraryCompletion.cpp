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

namespace hydcompletion {

// Reducing and drop valve between ideal sources: b2 = 0, so the spool settles at the
// lower hysteresis edge x = (opening - p_h/2)/b1 with b1 = Cs + (p1 - p2)*Cf, and the
// orifice passes q = x*sqrt(p1 - p2). Returns {x, q2}.
std::pair<double, double> pressureValveBetweenSources(const std::string& type, double p1, double p2)
{
    System s;
    add(s, type, "Valve");
    source(s, "Inlet", p1, "Valve", "P1");
    source(s, "Outlet", p2, "Valve", "P2");
    setParam(s, "Valve", "q_nom", "0.1"); // keep the spool below its stroke limit
    EXPECT_TRUE(run(s, 0, 0.5, 1e-4, 11));
    return {last(s, "Valve", "xv", "Value"), last(s, "Valve", "P2", "Flow")};
}

double pressureValveStiffness(double p1, double p2)
{
    const double pnom = 7e6, kcs = 1e-8, kcf = 1e-8;
    return std::sqrt(pnom) / kcs + (p1 - p2) / (kcf * std::sqrt(pnom));
}

} // namespace hydcompletion

TEST(HydraulicLibraryCompletion, PressureReducingValveClosesAbovePrefAndOpensBelow)
{
    // p_ref 2 MPa, p_h 0.5 MPa: outlet at 3 MPa shuts the valve (x = q = 0); at 1 MPa the
    // spool opens to (p_ref - p2 - p_h/2)/b1. Tolerance 1e-6 relative.
    auto [xClosed, qClosed] = pressureValveBetweenSources("HydraulicPressureReducingValve", 1e7, 3e6);
    EXPECT_EQ(xClosed, 0.0);
    EXPECT_EQ(qClosed, 0.0);
    auto [x, q] = pressureValveBetweenSources("HydraulicPressureReducingValve", 1e7, 1e6);
    const double xExpected = (2e6 - 1e6 - 2.5e5) / pressureValveStiffness(1e7, 1e6);
    EXPECT_NEAR(x, xExpected, 1e-6 * xExpected);
    EXPECT_NEAR(q, xExpected * std::sqrt(9e6), 1e-6 * xExpected * 3e3);
}

TEST(HydraulicLibraryCompletion, PressureDropValveOpensWhenTheDropExceedsPref)
{
    // p_ref 2 MPa, p_h 0.5 MPa: a drop of 1.5 MPa keeps it shut; a drop of 4 MPa opens it
    // to (p1 - p2 - p_ref - p_h/2)/b1. Tolerance 1e-6 relative.
    auto [xClosed, qClosed] = pressureValveBetweenSources("HydraulicPressureDropValve", 2.5e6, 1e6);
    EXPECT_EQ(xClosed, 0.0);
    EXPECT_EQ(qClosed, 0.0);
    auto [x, q] = pressureValveBetweenSources("HydraulicPressureDropValve", 5e6, 1e6);
    const double xExpected = (4e6 - 2e6 - 2.5e5) / pressureValveStiffness(5e6, 1e6);
    EXPECT_NEAR(x, xExpected, 1e-6 * xExpected);
    EXPECT_NEAR(q, xExpected * 2e3, 1e-6 * xExpected * 2e3);
}

TEST(HydraulicLibraryCompletion, PressureReducingValveHoldsItsOutletNearPrefInAModel)
{
    // Supply 10 MPa -> reducing valve -> volume -> orifice -> tank: the outlet settles
    // below p_ref (proportional droop) but well above half of it; every value finite.
    System s;
    add(s, "HydraulicPressureReducingValve", "Valve");
    source(s, "Supply", 1e7, "Valve", "P1");
    add(s, "HydraulicVolume", "Volume");
    add(s, "HydraulicTurbulentOrifice", "Load");
    add(s, "HydraulicTankC", "Tank");
    connectOk(s, "Valve", "P2", "Volume", "P1");
    connectOk(s, "Volume", "P2", "Load", "P1");
    connectOk(s, "Load", "P2", "Tank", "P1");
    ASSERT_TRUE(run(s, 0, 1.0, 1e-4, 101));
    const double p2 = last(s, "Valve", "P2", "Pressure");
    EXPECT_LT(p2, 2e6);
    EXPECT_GT(p2, 1e6);
    EXPECT_TRUE(allFinite(s, "Valve", {"P1", "P2"}, "Pressure"));
    EXPECT_TRUE(allFinite(s, "Valve", {"P1", "P2"}, "Flow"));
}

namespace hydcompletion {

struct FourPortFlows {
    double xv, qp, qt, qa, qb;
};

// Runs a 4-port spool valve between ideal sources PP 10 MPa, PT 0.1 MPa, PA 5 MPa,
// PB 3 MPa with a constant demand `in` until the spool has settled.
FourPortFlows fourPortValveBetweenSources(const std::string& type, double in)
{
    System s;
    add(s, type, "Valve");
    source(s, "P", 1e7, "Valve", "PP");
    source(s, "T", 1e5, "Valve", "PT");
    source(s, "A", 5e6, "Valve", "PA");
    source(s, "B", 3e6, "Valve", "PB");
    setParam(s, "Valve", "in#Value", std::to_string(in));
    EXPECT_TRUE(run(s, 0, 5.0, 1e-4, 11));
    EXPECT_TRUE(allFinite(s, "Valve", {"PP", "PT", "PA", "PB"}, "Flow"));
    return {last(s, "Valve", "xv", "Value"), last(s, "Valve", "PP", "Flow"), last(s, "Valve", "PT", "Flow"),
            last(s, "Valve", "PA", "Flow"), last(s, "Valve", "PB", "Flow")};
}

// Orifice coefficient of a spool edge (d = 0.01 m, Cq = 0.67) opened x over fraction f.
double edgeK(double f, double x, double rho)
{
    return 0.67 * f * pi * 0.01 * x * std::sqrt(2.0 / rho);
}

// Checks the port flows for edge coefficients between the sources above (all Zc = 0).
void expectFourPortFlows(const FourPortFlows& r, double Kpa, double Kpb, double Kat, double Kbt, double Kpt)
{
    const double qpa = Kpa * std::sqrt(1e7 - 5e6), qpb = Kpb * std::sqrt(1e7 - 3e6);
    const double qat = Kat * std::sqrt(5e6 - 1e5), qbt = Kbt * std::sqrt(3e6 - 1e5);
    const double qpt = Kpt * std::sqrt(1e7 - 1e5);
    const double tol = 1e-6 * (qpa + qpb + qat + qbt + qpt) + 1e-15;
    EXPECT_NEAR(r.qa, qpa - qat, tol);
    EXPECT_NEAR(r.qb, qpb - qbt, tol);
    EXPECT_NEAR(r.qp, -qpa - qpb - qpt, tol);
    EXPECT_NEAR(r.qt, qat + qbt + qpt, tol);
}

} // namespace hydcompletion

TEST(HydraulicLibraryCompletion, Valve42OpensPAandBTOnlyWithTheSpoolOut)
{
    // Spool at 0: every path shut. Spool at x_vmax: P-A and B-T follow the orifice law
    // over the full stroke; P-B and A-T stay shut. A negative demand is clipped to 0.
    const auto rest = fourPortValveBetweenSources("Hydraulic42Valve", -0.01);
    EXPECT_EQ(rest.xv, 0.0);
    expectFourPortFlows(rest, 0, 0, 0, 0, 0);
    const auto out = fourPortValveBetweenSources("Hydraulic42Valve", 0.01);
    EXPECT_NEAR(out.xv, 0.01, 1e-9);
    const double K = edgeK(1.0, 0.01, 890.0);
    expectFourPortFlows(out, K, 0, 0, K, 0);
}

TEST(HydraulicLibraryCompletion, Valve42TwoSwapsPBATforPABTAcrossTheStroke)
{
    // rho default 870. Spool at 0: P-B and A-T fully open; at x_vmax: P-A and B-T.
    const double K = edgeK(1.0, 0.01, 870.0);
    const auto rest = fourPortValveBetweenSources("Hydraulic42Valve2", 0.0);
    expectFourPortFlows(rest, 0, K, K, 0, 0);
    const auto out = fourPortValveBetweenSources("Hydraulic42Valve2", 0.01);
    EXPECT_NEAR(out.xv, 0.01, 1e-9);
    expectFourPortFlows(out, K, 0, 0, K, 0);
}

TEST(HydraulicLibraryCompletion, Valve43NeutralSupplyToTankBypassesPtoTAtCentre)
{
    // Centre: P-T open over f_c = 0.1 with x_c = x_vmax, plus the leakage of the -1e-6 m
    // overlaps. Fully out: the centre is shut (|xv| > p_c*x_vmax), P-A and B-T open.
    const double rho = 890.0, leak = edgeK(1.0, 1e-6, rho);
    const auto centre = fourPortValveBetweenSources("Hydraulic43ValveNeutralSupplyToTank", 0.0);
    expectFourPortFlows(centre, leak, leak, leak, leak, edgeK(0.1, 0.01, rho));
    const auto out = fourPortValveBetweenSources("Hydraulic43ValveNeutralSupplyToTank", 0.01);
    const double K = edgeK(1.0, 0.01 + 1e-6, rho);
    expectFourPortFlows(out, K, 0, 0, K, 0);
}

TEST(HydraulicLibraryCompletion, Valve43NeutralToTankDrainsAandBAtCentre)
{
    // Centre: A-T and B-T open over f_c = 0.1 (plus overlap leakage), P only leaks.
    // Fully reversed: P-B and A-T open, the centre shut.
    const double rho = 890.0, leak = edgeK(1.0, 1e-6, rho), Kc = edgeK(0.1, 0.01, rho);
    const auto centre = fourPortValveBetweenSources("Hydraulic43ValveNeutralToTank", 0.0);
    expectFourPortFlows(centre, leak, leak, leak + Kc, leak + Kc, 0);
    const auto back = fourPortValveBetweenSources("Hydraulic43ValveNeutralToTank", -0.01);
    EXPECT_NEAR(back.xv, -0.01, 1e-9);
    const double K = edgeK(1.0, 0.01 + 1e-6, rho);
    expectFourPortFlows(back, 0, K, K, 0, 0);
}

namespace hydcompletion {

struct ThreePortFlows {
    double xv, qp, qt, qa;
};

// A 3-port valve between ideal sources PP, PT and PA 5 MPa; `in` is set when given.
ThreePortFlows threePortValveBetweenSources(const std::string& type, const std::string& xvName, double pp,
                                            double pt, std::optional<double> in)
{
    System s;
    add(s, type, "Valve");
    source(s, "P", pp, "Valve", "PP");
    source(s, "T", pt, "Valve", "PT");
    source(s, "A", 5e6, "Valve", "PA");
    if (in) setParam(s, "Valve", "in#Value", std::to_string(*in));
    EXPECT_TRUE(run(s, 0, 2.0, 1e-4, 11));
    EXPECT_TRUE(allFinite(s, "Valve", {"PP", "PT", "PA"}, "Pressure"));
    return {last(s, "Valve", xvName, "Value"), last(s, "Valve", "PP", "Flow"), last(s, "Valve", "PT", "Flow"),
            last(s, "Valve", "PA", "Flow")};
}

} // namespace hydcompletion

TEST(HydraulicLibraryCompletion, Valve33OpensPAForwardAndATBackward)
{
    // P 10 MPa, T 0.1 MPa, A 5 MPa, rho 870. Spool at +x_vmax: only P-A, opened
    // x_vmax + 1e-6 (overlap -1e-6); at -x_vmax only A-T. Tolerance 1e-6 relative.
    const double K = edgeK(1.0, 0.01 + 1e-6, 870.0);
    const auto fwd = threePortValveBetweenSources("Hydraulic33Valve", "xv", 1e7, 1e5, 0.01);
    const double qpa = K * std::sqrt(5e6);
    EXPECT_NEAR(fwd.xv, 0.01, 1e-9);
    EXPECT_NEAR(fwd.qa, qpa, 1e-6 * qpa);
    EXPECT_NEAR(fwd.qp, -qpa, 1e-6 * qpa);
    EXPECT_EQ(fwd.qt, 0.0);
    const auto back = threePortValveBetweenSources("Hydraulic33Valve", "xv", 1e7, 1e5, -0.01);
    const double qat = K * std::sqrt(4.9e6);
    EXPECT_NEAR(back.qa, -qat, 1e-6 * qat);
    EXPECT_NEAR(back.qt, qat, 1e-6 * qat);
    EXPECT_EQ(back.qp, 0.0);
}

TEST(HydraulicLibraryCompletion, ShuttleValveConnectsAToTheLowerOfPAndT)
{
    // The higher of PP and PT pushes the spool to its end stop: P high -> xv = +x_vmax,
    // A-T open; T high -> xv = -x_vmax, P-A open (A then fills from the lower port P).
    const double K = edgeK(1.0, 0.01 + 1e-6, 890.0);
    const auto pHigh = threePortValveBetweenSources("Hydraulic33ShuttleValve", "xv_out", 1e7, 1e5, std::nullopt);
    EXPECT_DOUBLE_EQ(pHigh.xv, 0.01);
    const double qat = K * std::sqrt(5e6 - 1e5);
    EXPECT_NEAR(pHigh.qt, qat, 1e-6 * qat);
    EXPECT_EQ(pHigh.qp, 0.0);
    const auto tHigh = threePortValveBetweenSources("Hydraulic33ShuttleValve", "xv_out", 1e6, 1e7, std::nullopt);
    EXPECT_DOUBLE_EQ(tHigh.xv, -0.01);
    const double qpa = K * std::sqrt(5e6 - 1e6);
    EXPECT_NEAR(tHigh.qa, -qpa, 1e-6 * qpa);
    EXPECT_EQ(tHigh.qt, 0.0);
}

TEST(HydraulicLibraryCompletion, PressureControlledValveFollowsItsPilotPressures)
{
    // P1 10 MPa, P2 0.1 MPa, P_CLOSE 0.1 MPa. Pilot 1 MPa < p_ref + p_close: shut. Pilot
    // 5 MPa: x0 = (p_open - p_ref - p_close - p_h/2)/b1, b1 = Cs + Cf*(p1 - p2) (q_nom
    // raised so the stroke limit is not reached). Tolerance 1e-6 relative.
    for (double pOpen : {1e6, 5e6}) {
        System s;
        add(s, "HydraulicPressureControlledValve", "Valve");
        source(s, "In", 1e7, "Valve", "P1");
        source(s, "Out", 1e5, "Valve", "P2");
        source(s, "Open", pOpen, "Valve", "P_OPEN");
        source(s, "Close", 1e5, "Valve", "P_CLOSE");
        setParam(s, "Valve", "q_nom", "0.1");
        ASSERT_TRUE(run(s, 0, 0.5, 1e-4, 11));
        const double x = last(s, "Valve", "x0", "Value");
        const double q = last(s, "Valve", "P2", "Flow");
        const double xExpected = std::max((pOpen - 2e6 - 1e5 - 2.5e5) / pressureValveStiffness(1e7, 1e5), 0.0);
        EXPECT_NEAR(x, xExpected, 1e-6 * xExpected) << pOpen;
        EXPECT_NEAR(q, xExpected * std::sqrt(9.9e6), 1e-6 * xExpected * 3.2e3) << pOpen;
        EXPECT_EQ(last(s, "Valve", "P_OPEN", "Flow"), 0.0);
        EXPECT_DOUBLE_EQ(last(s, "Valve", "P_OPEN", "Pressure"), pOpen);
    }
}

TEST(HydraulicLibraryCompletion, PistonHeldStillPushesWithA1p1MinusA2p2)
{
    // Rod held at x = 0 by a fixed position, chambers fed by pressure sources: at rest
    // the force on the rod is A1*p1 - A2*p2 = 1e-3*10 MPa - 5e-4*2 MPa = 9 kN.
    // Tolerance 1e-6 relative after the (damped) chamber waves have settled.
    System s;
    add(s, "HydraulicPiston", "Piston");
    add(s, "HydraulicPressureSourceQ", "S1");
    add(s, "HydraulicPressureSourceQ", "S2");
    add(s, "MechanicFixedPosition", "Wall");
    connectOk(s, "S1", "P1", "Piston", "P1");
    connectOk(s, "S2", "P1", "Piston", "P2");
    connectOk(s, "Piston", "Pm1", "Wall", "Pm1");
    setParam(s, "S1", "p#Value", "1e7");
    setParam(s, "S2", "p#Value", "2e6");
    setParam(s, "Piston", "A2#Value", "5e-4");
    setParam(s, "Piston", "alpha#Value", "0.5"); // a lossless chamber between a source and a wall rings forever
    ASSERT_TRUE(run(s, 0, 0.1, 1e-4, 11));
    const double F = last(s, "Piston", "Pm1", "Force");
    EXPECT_NEAR(F, 9000.0, 9000.0 * 1e-6);
    EXPECT_NEAR(last(s, "Piston", "P1", "Pressure"), 1e7, 1e7 * 1e-6);
    EXPECT_TRUE(allFinite(s, "Piston", {"P1", "P2"}, "Pressure"));
}

TEST(HydraulicLibraryCompletion, MotorJloadSettlesWhereFrictionBalancesTheNetTorque)
{
    // 10 MPa -> motor -> 0.1 MPa, load torque 50 Nm, Bm = 1 Nms/rad, Jm = 0.1 kg m^2:
    // w settles at (Dm/(2 pi)*dp - T)/Bm and the flow at Dm/(2 pi)*w (no leakage).
    // Tolerance 1e-6 relative after 30 time constants Jm/Bm.
    System s;
    add(s, "HydraulicMotorJload", "Motor");
    source(s, "High", 1e7, "Motor", "P1");
    source(s, "Low", 1e5, "Motor", "P2");
    add(s, "MechanicTorqueTransformer", "Load");
    connectOk(s, "Motor", "Pm1", "Load", "P1");
    setParam(s, "Load", "T#Value", "50");
    setParam(s, "Motor", "Bm#Value", "1");
    ASSERT_TRUE(run(s, 0, 3.0, 1e-4, 31));
    const double k = 5e-5 / (2.0 * pi);
    const double w = (k * 9.9e6 - 50.0) / 1.0;
    EXPECT_NEAR(last(s, "Motor", "Pm1", "AngularVelocity"), w, 1e-6 * w);
    EXPECT_NEAR(last(s, "Motor", "P2", "Flow"), k * w, 1e-6 * k * w);
    EXPECT_NEAR(last(s, "Motor", "Pm1", "Torque"), 50.0, 1e-9);
    // The angle integrates w: after 3 s it lies between 0 and 3*w.
    const double angle = last(s, "Motor", "Pm1", "Angle");
    EXPECT_GT(angle, 2.5 * w);
    EXPECT_LT(angle, 3.0 * w);
}

TEST(HydraulicLibraryCompletion, OrificeCheckValveGUsesOrificeOneWayAndBackValveTheOther)
{
    // 9 MPa across, defaults: q = 2*A*dp/D with D^2 = (Cdt^2 (dh + 96 del^2 lo)^2 visc^2
    // + 2 del^4 dh^4 rho dp)/(Cdt^2 del^4 dh^4), A = Ao (3e-4) from Pc to Pp and Ab (1e-4)
    // from Pp to Pc. At this drop it is within 2e-5 of the orifice law
    // Cdt*A*sqrt(2 dp/rho). Tolerance 1e-9 relative.
    const double Cdt = 0.67, dh = 0.3, lo = 0.001, del = 0.02, visc = 0.12, rho = 860.0, dp = 9e6;
    const double lam = std::pow(Cdt * (dh + 96.0 * del * del * lo) * visc, 2);
    const double scale = Cdt * Cdt * std::pow(del * dh, 4);
    const double D = std::sqrt((lam + 2.0 * std::pow(del * dh, 4) * rho * dp) / scale);
    for (bool forward : {true, false}) {
        System s;
        add(s, "HydraulicOrificeCheckValveG", "Valve");
        source(s, "P", forward ? 1e6 : 1e7, "Valve", "Pp");
        source(s, "C", forward ? 1e7 : 1e6, "Valve", "Pc");
        ASSERT_TRUE(run(s, 0, 0.01, 1e-4, 11));
        const double A = forward ? 3e-4 : 1e-4;
        const double q = 2.0 * A * dp / D;
        EXPECT_NEAR(q, Cdt * A * std::sqrt(2.0 * dp / rho), 2e-5 * q);
        // qp > 0: flow leaves the valve at Pp.
        EXPECT_NEAR(last(s, "Valve", "Pp", "Flow"), forward ? q : -q, 1e-9 * q) << forward;
        EXPECT_NEAR(last(s, "Valve", "Pc", "Flow"), forward ? -q : q, 1e-9 * q) << forward;
        EXPECT_TRUE(allFinite(s, "Valve", {"Pp", "Pc"}, "Pressure"));
    }
}

TEST(HydraulicLibraryCompletion, Valve43GeneratedRoutesPAandBTForwardPBandATBackward)
{
    // Between ideal sources (PP 10, PT 0.1, PA 5, PB 3 MPa), rho 860, no underlap:
    // xv = +5 mm opens P-A and B-T by 5 mm, xv = -5 mm opens P-B and A-T; each edge
    // passes K*dp/(plam^2 + dp^2)^(1/4) (-> K*sqrt(dp) far above plam = 1e4 Pa) with
    // K = Cq*pi*Sd*x*sqrt(2/rho). Tolerance 1e-6 relative.
    for (double xv : {0.005, -0.005}) {
        System s;
        add(s, "HydraulicValve43", "Valve");
        source(s, "P", 1e7, "Valve", "Pp");
        source(s, "T", 1e5, "Valve", "Pt");
        source(s, "A", 5e6, "Valve", "Pa");
        source(s, "B", 3e6, "Valve", "Pb");
        setParam(s, "Valve", "xv#Value", std::to_string(xv));
        ASSERT_TRUE(run(s, 0, 0.01, 1e-4, 11));
        const double K = 1.4142135623730951 * 0.67 / std::sqrt(860.0) * 3.14159 * 0.01 * 0.005;
        auto edge = [K](double dp) { return K * dp / std::pow(1e8 + dp * dp, 0.25); };
        const double qa = xv > 0 ? edge(5e6) : -edge(4.9e6);
        const double qb = xv > 0 ? -edge(2.9e6) : edge(7e6);
        // Port flows are positive out of the valve into the node.
        EXPECT_NEAR(last(s, "Valve", "Pa", "Flow"), qa, 1e-6 * std::fabs(qa)) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pb", "Flow"), qb, 1e-6 * std::fabs(qb)) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pp", "Flow") + last(s, "Valve", "Pt", "Flow"), -qa - qb,
                    1e-6 * (std::fabs(qa) + std::fabs(qb)));
        EXPECT_DOUBLE_EQ(last(s, "Valve", "Pa", "Pressure"), 5e6);
    }
}

TEST(HydraulicLibraryCompletion, Valve43LSSensesTheLoadPortAndDrainsAtCentre)
{
    // Ideal sources PP 10, PT 0.1, PA 5, PB 3, PLS 2 MPa, defaults (overlaps 0.3 mm).
    // xv = 5 mm: P-A opens 4.7 mm, B-T 4.7 mm, LS-A the full 0.7 mm LS stroke; the LS
    // flow is drawn from Pls only. xv = 0: all main edges shut, LS drained to T over
    // Xls0. Edge law K*dp/(plam^2 + dp^2)^(1/4). Tolerance 1e-6 relative.
    const double Ks = 1.4142135623730951 * 0.67 / std::sqrt(860.0);
    auto S = [](double dp) { return dp / std::pow(1e8 + dp * dp, 0.25); };
    for (double xv : {0.005, 0.0}) {
        System s;
        add(s, "HydraulicValve43LS", "Valve");
        source(s, "P", 1e7, "Valve", "Pp");
        source(s, "T", 1e5, "Valve", "Pt");
        source(s, "A", 5e6, "Valve", "Pa");
        source(s, "B", 3e6, "Valve", "Pb");
        source(s, "LS", 2e6, "Valve", "Pls");
        setParam(s, "Valve", "xv#Value", std::to_string(xv));
        ASSERT_TRUE(run(s, 0, 0.01, 1e-4, 11));
        const double Kmain = 3.14159 * Ks * 0.01 * std::max(xv - 0.0003, 0.0);
        const double qa = Kmain * S(5e6);
        const double qb = -Kmain * S(2.9e6);
        const double qls = xv > 0 ? Ks * 0.01 * 0.0007 * S(5e6 - 2e6) : -Ks * 0.01 * 0.0003 * S(1.9e6);
        EXPECT_NEAR(last(s, "Valve", "Pa", "Flow"), qa, 1e-6 * std::fabs(qa) + 1e-15) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pb", "Flow"), qb, 1e-6 * std::fabs(qb) + 1e-15) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pls", "Flow"), qls, 1e-6 * std::fabs(qls)) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pt", "Flow"), -qb, 1e-6 * std::fabs(qb) + 1e-15) << xv;
    }
}

TEST(HydraulicLibraryCompletion, Valve63OCOpenCentreClosesAsTheSpoolMoves)
{
    // Ideal sources PP 10, PT 0.1, PA 5, PB 3, Pocp 8, Poct 0.1 MPa; Xoc0 set to 2 mm
    // (default 0 keeps the centre shut). xv = 0: only the centre Pocp -> Poct passes,
    // opened Xoc0; xv = 5 mm: centre shut, P-A and B-T open 5 mm (Sd 15 mm). Edge law
    // K*dp/(plam^2 + dp^2)^(1/4). Tolerance 1e-6 relative.
    const double k = 3.14159 * 1.4142135623730951 * 0.67 / std::sqrt(860.0) * 0.015;
    auto S = [](double dp) { return dp / std::pow(1e8 + dp * dp, 0.25); };
    for (double xv : {0.0, 0.005}) {
        System s;
        add(s, "HydraulicValve63OC", "Valve");
        source(s, "P", 1e7, "Valve", "Pp");
        source(s, "T", 1e5, "Valve", "Pt");
        source(s, "A", 5e6, "Valve", "Pa");
        source(s, "B", 3e6, "Valve", "Pb");
        source(s, "OCP", 8e6, "Valve", "Pocp");
        source(s, "OCT", 1e5, "Valve", "Poct");
        setParam(s, "Valve", "xv#Value", std::to_string(xv));
        setParam(s, "Valve", "Xoc0#Value", "0.002");
        ASSERT_TRUE(run(s, 0, 0.01, 1e-4, 11));
        const double qoc = xv == 0.0 ? k * 0.002 * S(7.9e6) : 0.0;
        const double qa = k * xv * S(5e6);
        EXPECT_NEAR(last(s, "Valve", "Poct", "Flow"), qoc, 1e-6 * qoc + 1e-15) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pocp", "Flow"), -qoc, 1e-6 * qoc + 1e-15) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pa", "Flow"), qa, 1e-6 * qa + 1e-15) << xv;
        EXPECT_NEAR(last(s, "Valve", "Pb", "Flow"), -k * xv * S(2.9e6), 1e-6 * qa + 1e-15) << xv;
    }
}

TEST(HydraulicLibraryCompletion, FuelTankGHeadFallsAsFuelIsDrawnAndVanishesWhenEmpty)
{
    // A flow source draws 1 l/s of fuel (700 kg/m^3): 0.7 kg/s is consumed (trapezoidal,
    // the first half step uses the start flow 0); the outlet pressure is
    // p0 + gx*hf*(massfuel/massfuelmax)*rho. With 1 kg in the tank it runs dry after
    // ~1.43 s and the pressure drops to 0. Tolerances 1e-9 relative.
    for (double m0 : {1000.0, 1.0}) {
        System s;
        add(s, "HydraulicFuelTankG", "Tank");
        add(s, "HydraulicFlowSourceQ", "Pump");
        connectOk(s, "Pump", "P1", "Tank", "PT");
        setParam(s, "Pump", "q#Value", "-1e-3");
        setParam(s, "Tank", "massfuel0#Value", std::to_string(m0));
        ASSERT_TRUE(run(s, 0, 2.0, 1e-3, 3));
        const double consumed = std::min(0.7 * (2.0 - 0.0005), m0 + 1e-4);
        const double mass = m0 - consumed;
        EXPECT_NEAR(last(s, "Tank", "consfuel", "Value"), consumed, 1e-9 * consumed) << m0;
        EXPECT_NEAR(last(s, "Tank", "massfuel", "Value"), mass, 1e-9 * m0) << m0;
        const double p = mass > 0 ? 1e5 + 9.82 * 5.0 * mass / 1000.0 * 700.0 : 0.0;
        EXPECT_NEAR(last(s, "Pump", "P1", "Pressure"), p, 1e-9 * 1e5) << m0;
    }
}
