// Two generated (Newton-solved) components completing Hopsan's default library:
// MechanicM3load1D (three masses with friction and stroke limits) and
// ElectricMotorGearScrewLink (DC motor, gear, screw and link). Each is checked against
// closed-form results of its own equations (docs/components/electric-mechanic-other.md) and
// in a small model that must run to its stop time with finite values.
#include "TestHelpers.h"

#include "core/Results.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace tlmhub;
using namespace tlmhub::test;

namespace lcgenerated {

// Logged samples of an output variable (a signal port of the component).
std::vector<double> genOutput(System& s, const std::string& comp, const std::string& port)
{
    Port* p = s.component(comp)->port(port);
    return loggedData(*p, NodeSignal::Value, s.numLoggedSamples());
}

// Every logged value of the model and every current node value is finite.
void expectGenAllFinite(const System& s)
{
    std::string where;
    EXPECT_FALSE(findNonFinite(s, where)) << where;
    EXPECT_FALSE(listLoggedVariables(s).empty());
}

// The M3load1D "Load" with one C-type force source per port (Zc = 0, so f = c exactly),
// every friction set to zero and bfc = 0. With fc = 0 the dry friction force is 0 but its
// Jacobian entry is not: the gate factor at a closed limit is 1e-9, so with bfc = 1 the
// Jacobian is off by about 1e-9 and the two damped Newton steps (weights 1, 0.67) leave a
// relative error of some 1e-10 of each step's change. bfc = 0 makes that entry exactly 0,
// the equations linear and the first Newton step exact.
void buildGenThreeMassRig(System& s, const double force[3], const double mass[3])
{
    add(s, "MechanicM3load1D", "Load");
    setParam(s, "Load", "bfc#Value", "0");
    for (int k = 0; k < 3; ++k) {
        const std::string n = std::to_string(k + 1);
        add(s, "MechanicTranslationalCSource", "F" + n);
        connectOk(s, "F" + n, "P1", "Load", "Pm" + n);
        setParam(s, "F" + n, "in_c#Value", std::to_string(force[k]));
        setParam(s, "F" + n, "in_z#Value", "0");
        setParam(s, "Load", "m" + n + "Mass#Value", std::to_string(mass[k]));
        setParam(s, "Load", "m" + n + "FrictionViscousCoeff#Value", "0");
        setParam(s, "Load", "m" + n + "FrictionCoulomb#Value", "0");
    }
    for (const char* pair : {"m12", "m13"}) {
        setParam(s, "Load", std::string(pair) + "FrictionViscousCoeff#Value", "0");
        setParam(s, "Load", std::string(pair) + "FrictionCoulomb#Value", "0");
    }
}

} // namespace lcgenerated

using namespace lcgenerated;

TEST(LibraryCompletionGeneratedM3load1D, UncoupledMassesFollowTheTrapezoidalRampExactly)
{
    // No friction: m_k dv_k/dt = -f_k on each port (x and v of Pm_k point along the port, so
    // a positive port force pushes its mass towards negative x). The component integrates
    // with the trapezoidal rule, which is exact for a constant force except that its first
    // step averages the start force (0) with f_k:
    //   v_k(t) = -f_k (t - dt/2) / m_k,  x_k(t_n) = -(f_k/m_k) dt^2 (n^2 + (n-1)^2) / 4.
    // The equations are linear here, so the first Newton step solves them; tolerance 1e-12
    // relative (round-off only).
    const double force[3] = {30.0, -8.0, 5.0};
    const double mass[3] = {10.0, 2.0, 0.5};
    const double dt = 1e-3;
    System s;
    buildGenThreeMassRig(s, force, mass);
    setParam(s, "Load", "m2Direction#Value", "-1");
    setParam(s, "Load", "m3PositionOffset#Value", "0.25");
    ASSERT_TRUE(run(s, 0, 1, dt, 101));

    const auto& t = s.logTime();
    const double dir[3] = {1.0, -1.0, 1.0};
    const double offset[3] = {0.0, 0.0, 0.25};
    for (int k = 0; k < 3; ++k) {
        const std::string n = std::to_string(k + 1);
        const auto v = loggedSlot(s, "Load", "Pm" + n, "Velocity");
        const auto x = loggedSlot(s, "Load", "Pm" + n, "Position");
        const auto f = loggedSlot(s, "Load", "Pm" + n, "Force");
        const auto me = loggedSlot(s, "Load", "Pm" + n, "EquivalentMass");
        const auto vOut = genOutput(s, "Load", "m" + n + "Velocity");
        const auto xOut = genOutput(s, "Load", "m" + n + "Position");
        const double a = force[k] / mass[k];
        ASSERT_EQ(v.size(), t.size());
        for (std::size_t i = 1; i < t.size(); ++i) {
            const double steps = std::round(t[i] / dt);
            const double vExpected = -a * (t[i] - dt / 2.0);
            const double xExpected = -a * dt * dt * (steps * steps + (steps - 1.0) * (steps - 1.0)) / 4.0;
            EXPECT_NEAR(v[i], vExpected, 1e-12 * std::fabs(a)) << "Pm" << n << " t=" << t[i];
            EXPECT_NEAR(x[i], xExpected, 1e-12 * std::fabs(a)) << "Pm" << n << " t=" << t[i];
            EXPECT_NEAR(f[i], force[k], 1e-12 * std::fabs(force[k])) << "Pm" << n;
            EXPECT_DOUBLE_EQ(me[i], mass[k]) << "Pm" << n;
            // Outputs: velocity -dir v, position offset - dir x.
            EXPECT_NEAR(vOut[i], -dir[k] * v[i], 1e-15) << "m" << n << "Velocity";
            EXPECT_NEAR(xOut[i], offset[k] - dir[k] * x[i], 1e-15) << "m" << n << "Position";
        }
    }
}

TEST(LibraryCompletionGeneratedM3load1D, CouplingForcesCancelInTheTotalMomentum)
{
    // Viscous coupling M1-M2 and M1-M3 only: internal forces cancel, so the trapezoidal rule
    // (which keeps linear invariants) gives sum m_k v_k = -(f1 + f2 + f3)(t - dt/2) exactly,
    // whatever the coupling does to each mass. Tolerance 1e-10 relative (Newton's LU round-off).
    // Also: M2 and M3 are dragged along by M1 (they have no force of their own here).
    const double force[3] = {40.0, 0.0, 0.0};
    const double mass[3] = {10.0, 2.0, 0.5};
    const double dt = 1e-3;
    System s;
    buildGenThreeMassRig(s, force, mass);
    setParam(s, "Load", "m12FrictionViscousCoeff#Value", "50");
    setParam(s, "Load", "m13FrictionViscousCoeff#Value", "20");
    ASSERT_TRUE(run(s, 0, 2, dt, 201));

    const auto& t = s.logTime();
    const auto v1 = loggedSlot(s, "Load", "Pm1", "Velocity");
    const auto v2 = loggedSlot(s, "Load", "Pm2", "Velocity");
    const auto v3 = loggedSlot(s, "Load", "Pm3", "Velocity");
    const auto f12 = genOutput(s, "Load", "m12FrictionForce");
    const auto f13 = genOutput(s, "Load", "m13FrictionForce");
    const double total = force[0] + force[1] + force[2];
    for (std::size_t i = 1; i < t.size(); ++i) {
        const double momentum = mass[0] * v1[i] + mass[1] * v2[i] + mass[2] * v3[i];
        const double expected = -total * (t[i] - dt / 2.0);
        EXPECT_NEAR(momentum, expected, 1e-10 * total * t.back()) << "t=" << t[i];
        EXPECT_NEAR(f12[i], -50.0 * (v1[i] - v2[i]), 1e-12 * total) << "t=" << t[i];
        EXPECT_NEAR(f13[i], -20.0 * (v1[i] - v3[i]), 1e-12 * total) << "t=" << t[i];
    }
    // After the transient (time constants below 0.05 s) all three share the acceleration
    // -f1 / (m1 + m2 + m3); M2 and M3 move the same way as M1.
    EXPECT_LT(v2.back(), 0.0);
    EXPECT_LT(v3.back(), 0.0);
    const std::size_t mid = t.size() / 2;
    const double aCommon = -total / (mass[0] + mass[1] + mass[2]);
    EXPECT_NEAR((v2.back() - v2[mid]) / (t.back() - t[mid]), aCommon, 1e-6 * std::fabs(aCommon));
    EXPECT_NEAR((v3.back() - v3[mid]) / (t.back() - t[mid]), aCommon, 1e-6 * std::fabs(aCommon));
}

TEST(LibraryCompletionGeneratedM3load1D, ViscousFrictionGivesTheSteadySpeeds)
{
    // With every viscous coefficient set, the speeds settle where the forces balance:
    //   0 = -f1 - (b1 + b12 + b13) v1 + b12 v2 + b13 v3
    //   0 = -f2 + b12 v1 - (b2 + b12) v2
    //   0 = -f3 + b13 v1 - (b3 + b13) v3
    // The trapezoidal rule has the same fixed point. Slowest time constant about 0.6 s; after
    // 20 s the transient is below 1e-12, so tolerance 1e-9 relative.
    const double force[3] = {30.0, -8.0, 5.0};
    const double mass[3] = {10.0, 2.0, 0.5};
    const double b[3] = {20.0, 4.0, 1.0};
    const double b12 = 5.0, b13 = 2.0;
    System s;
    buildGenThreeMassRig(s, force, mass);
    for (int k = 0; k < 3; ++k) {
        setParam(s, "Load", "m" + std::to_string(k + 1) + "FrictionViscousCoeff#Value", std::to_string(b[k]));
    }
    setParam(s, "Load", "m12FrictionViscousCoeff#Value", std::to_string(b12));
    setParam(s, "Load", "m13FrictionViscousCoeff#Value", std::to_string(b13));
    ASSERT_TRUE(run(s, 0, 20, 1e-3, 11));

    // v2 = (b12 v1 - f2)/(b2 + b12), v3 = (b13 v1 - f3)/(b3 + b13), into the first equation.
    const double k2 = b[1] + b12, k3 = b[2] + b13;
    const double v1 = (-force[0] - b12 * force[1] / k2 - b13 * force[2] / k3)
                      / (b[0] + b12 + b13 - b12 * b12 / k2 - b13 * b13 / k3);
    const double v2 = (b12 * v1 - force[1]) / k2;
    const double v3 = (b13 * v1 - force[2]) / k3;
    const double tol = 1e-9 * std::fabs(v1);
    EXPECT_NEAR(loggedSlot(s, "Load", "Pm1", "Velocity").back(), v1, tol);
    EXPECT_NEAR(loggedSlot(s, "Load", "Pm2", "Velocity").back(), v2, tol);
    EXPECT_NEAR(loggedSlot(s, "Load", "Pm3", "Velocity").back(), v3, tol);
    // Friction outputs: to ground dir*b*v, between the pairs -b12 (v1 - v2) (force on M1).
    EXPECT_NEAR(genOutput(s, "Load", "m1FrictionForce").back(), b[0] * v1, 1e-9 * std::fabs(b[0] * v1));
    EXPECT_NEAR(genOutput(s, "Load", "m2FrictionForce").back(), b[1] * v2, 1e-9 * std::fabs(b[0] * v1));
    EXPECT_NEAR(genOutput(s, "Load", "m12FrictionForce").back(), -b12 * (v1 - v2), 1e-9 * std::fabs(b[0] * v1));
    EXPECT_NEAR(genOutput(s, "Load", "m13FrictionForce").back(), -b13 * (v1 - v3), 1e-9 * std::fabs(b[0] * v1));
}

TEST(LibraryCompletionGeneratedM3load1D, DryFrictionHoldsBelowAndSlidesAboveItsLevel)
{
    // Dry friction fc between M1 and ground (bfc = 1), nothing else.
    // Above fc the mass slides with dv1/dt = -(f1 - fc)/m1 once |v1| > fc dt/(2 m1).
    // Below fc the numerical friction -2 m1 v1/dt is not saturated; its fixed point in the
    // trapezoidal step is a creep speed v1 = -f1 dt/(2 m1) (friction force equal to f1),
    // a thousandth of the speed a free mass would have after 1 s. Tolerance 1e-9 relative.
    const double mass[3] = {10.0, 2.0, 0.5};
    const double dt = 1e-3, fc = 100.0;
    for (double f1 : {50.0, 150.0}) {
        const double force[3] = {f1, 0.0, 0.0};
        System s;
        buildGenThreeMassRig(s, force, mass);
        setParam(s, "Load", "bfc#Value", "1");
        setParam(s, "Load", "m1FrictionCoulomb#Value", std::to_string(fc));
        ASSERT_TRUE(run(s, 0, 1, dt, 101));
        const auto& t = s.logTime();
        const auto v = loggedSlot(s, "Load", "Pm1", "Velocity");
        const auto fr = genOutput(s, "Load", "m1FrictionForce");
        if (f1 < fc) {
            const double creep = -f1 * dt / (2.0 * mass[0]);
            EXPECT_NEAR(v.back(), creep, 1e-9 * std::fabs(creep)) << "f1=" << f1;
            // m1FrictionForce = b1 v1 - fr1 with fr1 = -2 m1 v1/dt = f1: the output is -f1.
            EXPECT_NEAR(fr.back(), -f1, 1e-9 * f1) << "f1=" << f1;
        } else {
            const std::size_t mid = t.size() / 2;
            const double slope = (v.back() - v[mid]) / (t.back() - t[mid]);
            const double expected = -(f1 - fc) / mass[0];
            EXPECT_NEAR(slope, expected, 1e-9 * std::fabs(expected)) << "f1=" << f1;
            EXPECT_NEAR(fr.back(), -fc, 1e-9 * fc) << "f1=" << f1;
        }
    }
}

TEST(LibraryCompletionGeneratedM3load1D, StopsAtItsStrokeLimit)
{
    // A force of 30 N drives M1 towards negative x; m1PositionLimitNeg = -0.02 m stops it
    // (free, it would reach x = -1.5 m in 1 s). The position is clamped to the limit and the
    // velocity is gated to ~0 (the derivative factor at a limit is 1e-9).
    const double force[3] = {30.0, 0.0, 0.0};
    const double mass[3] = {10.0, 2.0, 0.5};
    System s;
    buildGenThreeMassRig(s, force, mass);
    setParam(s, "Load", "m1PositionLimitNeg#Value", "-0.02");
    ASSERT_TRUE(run(s, 0, 1, 1e-3, 101));
    const auto x = loggedSlot(s, "Load", "Pm1", "Position");
    const auto v = loggedSlot(s, "Load", "Pm1", "Velocity");
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_GE(x[i], -0.02) << "sample " << i;
    EXPECT_DOUBLE_EQ(x.back(), -0.02);
    EXPECT_LT(std::fabs(v.back()), 1e-6);
    EXPECT_DOUBLE_EQ(genOutput(s, "Load", "m1Position").back(), 0.02);
}

TEST(LibraryCompletionGeneratedM3load1D, SpringModelWithDefaultsRunsWithFiniteValues)
{
    // Defaults (dry and viscous friction everywhere): a sine force on M1, M2 and M3 held by
    // springs to walls. Runs to its stop time, all values finite, and the masses move.
    System s;
    add(s, "SignalSineWave", "Wave");
    add(s, "MechanicForceTransformer", "Force");
    add(s, "MechanicM3load1D", "Load");
    add(s, "MechanicTranslationalSpring", "Spring2");
    add(s, "MechanicTranslationalSpring", "Spring3");
    add(s, "MechanicFixedPosition", "Wall2");
    add(s, "MechanicFixedPosition", "Wall3");
    connectOk(s, "Wave", "out", "Force", "F");
    connectOk(s, "Force", "P1", "Load", "Pm1");
    connectOk(s, "Load", "Pm2", "Spring2", "P1");
    connectOk(s, "Spring2", "P2", "Wall2", "Pm1");
    connectOk(s, "Load", "Pm3", "Spring3", "P1");
    connectOk(s, "Spring3", "P2", "Wall3", "Pm1");
    setParam(s, "Wave", "y_A#Value", "500");
    setParam(s, "Wave", "f#Value", "0.5");
    ASSERT_TRUE(run(s, 0, 5, 1e-3, 501));
    ASSERT_NEAR(s.logTime().back(), 5.0, 1e-9);
    expectGenAllFinite(s);
    double maxSpeed1 = 0.0, maxSpeed2 = 0.0;
    for (double v : loggedSlot(s, "Load", "Pm1", "Velocity")) maxSpeed1 = std::max(maxSpeed1, std::fabs(v));
    for (double v : loggedSlot(s, "Load", "Pm2", "Velocity")) maxSpeed2 = std::max(maxSpeed2, std::fabs(v));
    EXPECT_GT(maxSpeed1, 1e-3);
    EXPECT_GT(maxSpeed2, 1e-4);
}

namespace lcgenerated {

// ElectricMotorGearScrewLink "Motor": Pel1 at a stiff voltage U (C source, Zc = 0), Pel2
// grounded, Pmr1 against a torque source T (Zc = 0).
void buildGenScrewLinkRig(System& s, double u, double torque)
{
    add(s, "ElectricCSource", "Supply");
    add(s, "ElectricGround", "Ground");
    add(s, "ElectricMotorGearScrewLink", "Motor");
    add(s, "MechanicTorqueTransformer", "Load");
    connectOk(s, "Supply", "P1", "Motor", "Pel1");
    connectOk(s, "Motor", "Pel2", "Ground", "Pel1");
    connectOk(s, "Motor", "Pmr1", "Load", "P1");
    setParam(s, "Supply", "in_c#Value", std::to_string(u));
    setParam(s, "Supply", "in_z#Value", "0");
    setParam(s, "Load", "T#Value", std::to_string(torque));
}

// Parameters with time constants of milliseconds: g = 2, Ke = 0.5, Ra = 1, Bm = 0.1,
// Jm = 0.01, JL = 0.1, pitch = 0.01 m/rad, la = 0.02 m (la/pitch = 2), wide angle limits.
void setGenScrewLinkParams(System& s)
{
    setParam(s, "Motor", "gearRatio#Value", "2");
    setParam(s, "Motor", "Ke#Value", "0.5");
    setParam(s, "Motor", "Ra#Value", "1");
    setParam(s, "Motor", "Bm#Value", "0.1");
    setParam(s, "Motor", "Jm#Value", "0.01");
    setParam(s, "Motor", "JL#Value", "0.1");
    setParam(s, "Motor", "pitch#Value", "0.01");
    setParam(s, "Motor", "la#Value", "0.02");
    setParam(s, "Motor", "thetamin#Value", "-1000");
    setParam(s, "Motor", "thetamax#Value", "1000");
}

} // namespace lcgenerated

TEST(LibraryCompletionGeneratedScrewLink, LockedLinkDrawsTheStallCurrent)
{
    // thetamin = thetamax = 0 locks the link: w is gated to ~0, so there is no back-EMF and
    // the armature current is U/Ra (defaults Ra = 0.04 ohm). Tolerance 1e-6 relative (the
    // gate leaves w of order 1e-9 times the free acceleration step).
    const double u = 12.0, ra = 0.04;
    System s;
    buildGenScrewLinkRig(s, u, 0.0);
    setParam(s, "Motor", "thetamin#Value", "0");
    setParam(s, "Motor", "thetamax#Value", "0");
    ASSERT_TRUE(run(s, 0, 0.1, 1e-4, 11));
    const double i = u / ra;
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pel2", "Current").back(), i, 1e-6 * i);
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pel1", "Current").back(), -i, 1e-6 * i);
    EXPECT_NEAR(genOutput(s, "Motor", "Pin").back(), u * i, 1e-6 * u * i);
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pmr1", "Angle").back(), 0.0, 1e-12);
    EXPECT_LT(std::fabs(loggedSlot(s, "Motor", "Pmr1", "AngularVelocity").back()), 1e-6);
    // Generated torque Ke i at standstill (Tm0 = 0).
    EXPECT_NEAR(genOutput(s, "Motor", "tormg").back(), 0.13 * i, 1e-6 * 0.13 * i);
}

TEST(LibraryCompletionGeneratedScrewLink, FreeLinkReachesTheBackEmfSpeed)
{
    // No load torque, Tm0 = 0 (so gear and screw friction, proportional to |T|, vanish).
    // With r = la/pitch the equations are
    //   (JL + g Jm) p^2 dw/dt = g Ke i p^2 - g^2 (la^2 + Bm p^2) w,   i = (U - g Ke r w)/Ra,
    // so the steady speed is w = Ke U / (g (Ke^2 r + Ra (r^2 + Bm))), the motor speed output
    // wm = g w, and i follows from the back-EMF g Ke r w. Time constant about 6.5 ms; after
    // 0.5 s the transient is gone: tolerance 1e-9 relative.
    const double u = 10.0, g = 2.0, ke = 0.5, ra = 1.0, bm = 0.1, r = 2.0;
    System s;
    buildGenScrewLinkRig(s, u, 0.0);
    setGenScrewLinkParams(s);
    ASSERT_TRUE(run(s, 0, 0.5, 1e-4, 101));
    const double w = ke * u / (g * (ke * ke * r + ra * (r * r + bm)));
    const double i = (u - g * ke * r * w) / ra;
    const auto wLink = loggedSlot(s, "Motor", "Pmr1", "AngularVelocity");
    EXPECT_NEAR(wLink.back(), w, 1e-9 * w);
    EXPECT_NEAR(genOutput(s, "Motor", "wm").back(), g * w, 1e-9 * w);
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pel2", "Current").back(), i, 1e-9 * i);
    EXPECT_NEAR(genOutput(s, "Motor", "tormg").back(), i * ke - bm * g * w, 1e-9 * i * ke);
    EXPECT_NEAR(genOutput(s, "Motor", "Pout").back(), 0.0, 1e-12);
    // The link angle, integrated twice from the acceleration, advances at the same speed.
    const auto& t = s.logTime();
    const auto a = loggedSlot(s, "Motor", "Pmr1", "Angle");
    const std::size_t n = t.size() - 1;
    EXPECT_NEAR((a[n] - a[n - 10]) / (t[n] - t[n - 10]), w, 1e-9 * w);
}

TEST(LibraryCompletionGeneratedScrewLink, LoadTorqueAndFrictionLowerTheSteadySpeed)
{
    // Load torque T = 0.05 Nm, break-away torque Tm0 = 0.02 Nm, gear friction myg = 0.05,
    // screw friction mys = 0.1, wc = 0.01 rad/s (so the friction is saturated at the speed
    // reached). Steady state of the link equation, A = 0 with s = +1:
    //   p^2 (T - g Ke i) + g^2 (la^2 + Bm p^2) w + g p^2 Tm0 + la^2 (g^2 myg + mys) |T| = 0,
    //   i = (U - g Ke r w)/Ra.
    // Tolerance 1e-9 relative.
    const double u = 10.0, g = 2.0, ke = 0.5, ra = 1.0, bm = 0.1, p = 0.01, la = 0.02, r = la / p;
    const double torque = 0.05, tm0 = 0.02, myg = 0.05, mys = 0.1;
    System s;
    buildGenScrewLinkRig(s, u, torque);
    setGenScrewLinkParams(s);
    setParam(s, "Motor", "Tm0#Value", std::to_string(tm0));
    setParam(s, "Motor", "myg#Value", std::to_string(myg));
    setParam(s, "Motor", "mys#Value", std::to_string(mys));
    setParam(s, "Motor", "wc#Value", "0.01");
    ASSERT_TRUE(run(s, 0, 0.5, 1e-4, 101));
    const double p2 = p * p;
    const double friction = g * p2 * tm0 + la * la * (g * g * myg + mys) * torque;
    const double w = (p2 * g * ke * u / ra - p2 * torque - friction)
                     / (g * g * (la * la + bm * p2) + p2 * g * g * ke * ke * r / ra);
    ASSERT_GT(w, 0.01);
    const double i = (u - g * ke * r * w) / ra;
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pmr1", "AngularVelocity").back(), w, 1e-9 * w);
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pel2", "Current").back(), i, 1e-9 * i);
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pmr1", "Torque").back(), torque, 1e-12);
    EXPECT_NEAR(genOutput(s, "Motor", "Pout").back(), torque * w, 1e-9 * torque * w);
    EXPECT_NEAR(genOutput(s, "Motor", "tormg").back(), i * ke - bm * g * w - tm0, 1e-9 * i * ke);
}

TEST(LibraryCompletionGeneratedScrewLink, ModelWithDefaultsRunsWithFiniteValues)
{
    // Defaults but thetamax = 0.005 rad: a 24 V step through a supply impedance, the link on
    // a torsional spring and an inertia. Runs to its stop time with all values finite, and
    // the link (about 8 mrad/s free) reaches its upper limit and stays there.
    System s;
    add(s, "SignalStep", "Step");
    add(s, "ElectricCSource", "Supply");
    add(s, "ElectricGround", "Ground");
    add(s, "ElectricMotorGearScrewLink", "Motor");
    add(s, "MechanicTorsionalSpring", "Spring");
    add(s, "MechanicRotationalInertia", "Inertia");
    add(s, "MechanicTorqueTransformer", "Load");
    connectOk(s, "Step", "out", "Supply", "in_c");
    connectOk(s, "Supply", "P1", "Motor", "Pel1");
    connectOk(s, "Motor", "Pel2", "Ground", "Pel1");
    connectOk(s, "Motor", "Pmr1", "Spring", "P1");
    connectOk(s, "Spring", "P2", "Inertia", "P1");
    connectOk(s, "Inertia", "P2", "Load", "P1");
    setParam(s, "Step", "y_A#Value", "24");
    setParam(s, "Step", "t_step#Value", "0.1");
    setParam(s, "Supply", "in_z#Value", "0.01");
    setParam(s, "Motor", "thetamax#Value", "0.005");
    ASSERT_TRUE(run(s, 0, 2, 1e-4, 201));
    ASSERT_NEAR(s.logTime().back(), 2.0, 1e-9);
    expectGenAllFinite(s);
    EXPECT_NEAR(loggedSlot(s, "Motor", "Pmr1", "Angle").back(), 0.005, 1e-9);
}
