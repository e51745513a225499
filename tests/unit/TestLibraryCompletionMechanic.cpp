// Mechanic types completing Hopsan's default library (issue 21): MechanicGear and
// MechanicSwashPlate, checked against their kinematics and a constant-torque acceleration.
#include "TestHelpers.h"

#include "core/Results.h"

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace tlmhub;
using namespace tlmhub::test;

TEST(LibraryCompletionMechanicGear, SpeedRatioAndConstantTorqueAcceleration)
{
    // Torque sources at both shafts (Zc = 0): Jg dw2/dt = g T1 - T2 - Bg w2, w1 = -g w2.
    // With myfric = 0 and Bg = 0, w2 is an exact ramp under the trapezoidal rule (1e-9
    // relative). With the default myfric the friction's slip is zero, but its Jacobian entry
    // is not, so the two damped Newton steps land slightly off: within 1e-4 relative.
    System s;
    add(s, "MechanicTorqueTransformer", "Motor");
    add(s, "MechanicGear", "Gear");
    add(s, "MechanicTorqueTransformer", "Load");
    connectOk(s, "Motor", "P1", "Gear", "Pmr1");
    connectOk(s, "Gear", "Pmr2", "Load", "P1");
    setParam(s, "Motor", "T#Value", "10");
    setParam(s, "Load", "T#Value", "5");
    setParam(s, "Gear", "gearRatio#Value", "2");
    setParam(s, "Gear", "Jg#Value", "0.5");
    setParam(s, "Gear", "myfric#Value", "0");
    ASSERT_TRUE(run(s, 0, 1, 1e-3, 101));
    const auto w1 = loggedSlot(s, "Gear", "Pmr1", "AngularVelocity");
    const auto w2 = loggedSlot(s, "Gear", "Pmr2", "AngularVelocity");
    const auto t1 = loggedSlot(s, "Gear", "Pmr1", "Torque");
    const auto t2 = loggedSlot(s, "Gear", "Pmr2", "Torque");
    const auto je1 = loggedSlot(s, "Gear", "Pmr1", "EquivalentInertia");
    const auto& t = s.logTime();
    EXPECT_NEAR(std::fabs(t1.back()), 10.0, 1e-12);
    EXPECT_NEAR(std::fabs(t2.back()), 5.0, 1e-12);
    const double accel = (2.0 * t1.back() - t2.back()) / 0.5;
    EXPECT_GT(std::fabs(accel), 1.0);
    for (std::size_t k = 1; k < t.size(); ++k) {
        EXPECT_NEAR(w2[k], accel * t[k], 1e-9 * std::fabs(accel)) << "t=" << t[k];
        EXPECT_NEAR(w1[k], -2.0 * w2[k], 1e-12 * std::fabs(w2[k]) + 1e-15) << "t=" << t[k];
    }
    EXPECT_NEAR(je1.back(), 0.5 / 4.0, 1e-15);

    setParam(s, "Gear", "myfric#Value", "0.01");
    ASSERT_TRUE(run(s, 0, 1, 1e-3, 101));
    EXPECT_NEAR(loggedSlot(s, "Gear", "Pmr2", "AngularVelocity").back(), accel * t.back(), 1e-4 * std::fabs(accel));
}

TEST(LibraryCompletionMechanicGear, ViscousFrictionGivesTheSteadySpeed)
{
    // With Bg > 0 the speed settles at w2 = (g T1 - T2) / Bg (time constant Jg / Bg = 0.05 s).
    System s;
    add(s, "MechanicTorqueTransformer", "Motor");
    add(s, "MechanicGear", "Gear");
    add(s, "MechanicTorqueTransformer", "Load");
    connectOk(s, "Motor", "P1", "Gear", "Pmr1");
    connectOk(s, "Gear", "Pmr2", "Load", "P1");
    setParam(s, "Motor", "T#Value", "10");
    setParam(s, "Load", "T#Value", "5");
    setParam(s, "Gear", "gearRatio#Value", "3");
    setParam(s, "Gear", "Jg#Value", "0.5");
    setParam(s, "Gear", "Bg#Value", "10");
    ASSERT_TRUE(run(s, 0, 2, 1e-3, 101));
    const double t1 = loggedSlot(s, "Gear", "Pmr1", "Torque").back();
    const double t2 = loggedSlot(s, "Gear", "Pmr2", "Torque").back();
    const double w2 = loggedSlot(s, "Gear", "Pmr2", "AngularVelocity").back();
    EXPECT_NEAR(w2, (3.0 * t1 - t2) / 10.0, 1e-9);
    EXPECT_NEAR(std::fabs(w2), 2.5, 1e-9);
    EXPECT_NEAR(loggedSlot(s, "Gear", "Pmr1", "AngularVelocity").back(), -3.0 * w2, 1e-12);
}

TEST(LibraryCompletionMechanicSwashPlate, PistonKinematicsAndShaftTorque)
{
    // Two pistons, each behind a force source F (Zc = 0); constant shaft speed w. The shaft
    // angle is the trapezoidal integral of w from 0, a = w (t - h/2) on the step grid. Piston i:
    // x = s sin(a - i pi), v = s w cos(a - i pi), s = r tan(angle); torque = sum F s cos(...).
    const double r = 0.05, angle = 0.3, w = 20.0, h = 1e-4;
    System s;
    add(s, "MechanicSwashPlate", "Plate");
    add(s, "MechanicTranslationalCSource", "F0");
    add(s, "MechanicTranslationalCSource", "F1");
    connectOk(s, "Plate", "P1", "F0", "P1");
    connectOk(s, "Plate", "P1", "F1", "P1");
    setParam(s, "F0", "in_c#Value", "1000");
    setParam(s, "F1", "in_c#Value", "400");
    setParam(s, "Plate", "r#Value", "0.05");
    setParam(s, "Plate", "angle#Value", "0.3");
    setParam(s, "Plate", "movement#Value", "20");
    ASSERT_TRUE(run(s, 0, 0.5, h, 51));
    const double stroke = r * std::tan(angle);
    const auto x0 = loggedSlot(s, "F0", "P1", "Position");
    const auto v1 = loggedSlot(s, "F1", "P1", "Velocity");
    const auto f0 = loggedSlot(s, "F0", "P1", "Force");
    Port* tp = s.component("Plate")->port("torque");
    const auto torque = loggedData(*tp, NodeSignal::Value, s.numLoggedSamples());
    const auto& t = s.logTime();
    for (std::size_t k = 1; k < t.size(); ++k) {
        const double a = w * (t[k] - h / 2.0);
        EXPECT_NEAR(x0[k], stroke * std::sin(a), 1e-9) << "t=" << t[k];
        EXPECT_NEAR(v1[k], stroke * w * std::cos(a - 3.14159265358979323846), 1e-8) << "t=" << t[k];
        EXPECT_NEAR(f0[k], 1000.0, 1e-12);
        EXPECT_NEAR(torque[k], (1000.0 - 400.0) * stroke * std::cos(a), 1e-7) << "t=" << t[k];
    }
}

TEST(LibraryCompletionCombustionEngine, TorqueIsThePowerOverSpeedCappedByTheCurve)
{
    // Shaft speed imposed by a Q source. c = limit(-in * P_max / w, 0, curve(w)), Zc = 0.
    namespace fs = std::filesystem;
    const fs::path curve = fs::temp_directory_path() / "tlmhub-combustion-engine-test.csv";
    {
        std::ofstream out(curve);
        out << "-2000,100\n-500,300\n0,300\n";
    }
    auto torqueAt = [&](double w, double throttle) -> double {
        System s;
        add(s, "CombustionEngine", "Engine");
        add(s, "MechanicAngularVelocityTransformer", "Shaft");
        add(s, "SignalConstant", "Throttle");   // `in` is a required read port, as in Hopsan
        connectOk(s, "Engine", "P1", "Shaft", "out");
        connectOk(s, "Throttle", "y", "Engine", "in");
        setParam(s, "Engine", "Characteristics", curve.string());
        setParam(s, "Engine", "P_max", "1e5");
        setParam(s, "Throttle", "y#Value", std::to_string(throttle));
        setParam(s, "Shaft", "omega#Value", std::to_string(w));
        if (!run(s, 0, 0.01, 1e-3, 11)) {
            ADD_FAILURE() << "did not run";
            return NAN;
        }
        EXPECT_NEAR(loggedSlot(s, "Engine", "P1", "CharImpedance").back(), 0.0, 0.0);
        return loggedSlot(s, "Engine", "P1", "WaveVariable").back();
    };
    EXPECT_NEAR(torqueAt(-1000.0, 0.5), 50.0, 1e-12);             // 0.5 * 1e5 / 1000 under the cap
    EXPECT_NEAR(torqueAt(-1250.0, 5.0), 200.0, 1e-12);            // 400 over the cap 100 + (300 - 100) * 0.5
    EXPECT_NEAR(torqueAt(-100.0, 1.0), 300.0, 1e-12);             // 1000 capped by the curve
    EXPECT_NEAR(torqueAt(100.0, 1.0), 0.0, 1e-12);                // never negative
    fs::remove(curve);
}

TEST(LibraryCompletionCombustionEngine, AMissingCurveStopsTheSimulation)
{
    System s;
    add(s, "CombustionEngine", "Engine");
    add(s, "MechanicAngularVelocityTransformer", "Shaft");
    add(s, "SignalConstant", "Throttle");
    connectOk(s, "Engine", "P1", "Shaft", "out");
    connectOk(s, "Throttle", "y", "Engine", "in");
    setParam(s, "Engine", "Characteristics", "/nonexistent/tlmhub-engine.csv");
    EXPECT_FALSE(run(s, 0, 0.01, 1e-3, 11));
}

TEST(LibraryCompletionForks, TraverseAndTiltReachTheirViscousTerminalSpeeds)
{
    // Constant torque on P1 (Zc = 0): the carriage is a mass m with friction B pushed by
    // c1 / r, so v -> c1 / (r B) with time constant m / B = 0.1 s, and P1 turns at -v / r.
    // Pistons: c3 - c2 = 100 N on the lever r2 = 0.1 (no dry friction) tilts the forks down at
    // w -> (c2 - c3) r2 / Brot = -1 rad/s (time constant J / Brot = 0.02 s); piston speeds
    // are -+ w r2. The inputs were 0 before the first step, so under the trapezoidal rule
    // every response lags half a step: compared at te = t - h/2, tolerances 1e-7 (speeds,
    // traverse) and 1e-6 (angle).
    System s;
    add(s, "MechanicTorqueTransformer", "Pinion");
    add(s, "Forks", "Forks");
    add(s, "MechanicTranslationalCSource", "Piston2");
    add(s, "MechanicTranslationalCSource", "Piston3");
    connectOk(s, "Pinion", "P1", "Forks", "P1");
    connectOk(s, "Forks", "P2", "Piston2", "P1");
    connectOk(s, "Forks", "P3", "Piston3", "P1");
    setParam(s, "Pinion", "T#Value", "1");
    setParam(s, "Forks", "B#Value", "1000");
    setParam(s, "Forks", "Kfrot#Value", "0");
    setParam(s, "Piston3", "in_c#Value", "100");
    ASSERT_TRUE(run(s, 0, 1, 1e-3, 101));
    const double c1 = loggedSlot(s, "Forks", "P1", "WaveVariable").back();
    EXPECT_NEAR(std::fabs(c1), 1.0, 1e-12);
    const double vTerminal = c1 / (0.1 * 1000.0);
    const double w1 = loggedSlot(s, "Forks", "P1", "AngularVelocity").back();
    const double te = 1.0 - 0.5e-3;
    EXPECT_NEAR(w1, -vTerminal / 0.1 * (1.0 - std::exp(-te / 0.1)), 1e-7);
    Port* xPort = s.component("Forks")->port("x");
    const auto x = loggedData(*xPort, NodeSignal::Value, s.numLoggedSamples());
    // Travelled distance of a first-order start from rest: v (t - tau (1 - e^{-t/tau})).
    EXPECT_NEAR(x.back() - (-0.6), vTerminal * (te - 0.1 * (1.0 - std::exp(-te / 0.1))), 1e-7);
    EXPECT_NEAR(loggedSlot(s, "Forks", "P3", "Velocity").back(), -0.1, 1e-7);
    EXPECT_NEAR(loggedSlot(s, "Forks", "P2", "Velocity").back(), 0.1, 1e-7);
    Port* aPort = s.component("Forks")->port("a");
    const auto a = loggedData(*aPort, NodeSignal::Value, s.numLoggedSamples());
    const double pi = 3.14159265358979323846;
    EXPECT_NEAR(a.back(), pi / 2.0 - (te - 0.02 * (1.0 - std::exp(-te / 0.02))), 1e-6);
    EXPECT_NEAR(loggedSlot(s, "Forks", "P3", "Position").back(), a.back() * 0.1 - 0.5, 1e-12);
    EXPECT_NEAR(loggedSlot(s, "Forks", "P2", "Position").back(), -a.back() * 0.1 - 0.5, 1e-12);
}

TEST(LibraryCompletionForks, EndStopsHoldTheCarriage)
{
    // The carriage starts at x_min = -0.6. A wave c1 < 0 pushes it into the stop, where it
    // stays with zero speed; c1 > 0 moves it away.
    for (const char* torque : {"100", "-100"}) {
        System s;
        add(s, "MechanicTorqueTransformer", "Pinion");
        add(s, "Forks", "Forks");
        add(s, "MechanicTranslationalCSource", "Piston2");
        add(s, "MechanicTranslationalCSource", "Piston3");
        connectOk(s, "Pinion", "P1", "Forks", "P1");
        connectOk(s, "Forks", "P2", "Piston2", "P1");
        connectOk(s, "Forks", "P3", "Piston3", "P1");
        setParam(s, "Pinion", "T#Value", torque);
        ASSERT_TRUE(run(s, 0, 0.5, 1e-3, 51));
        Port* xPort = s.component("Forks")->port("x");
        const auto x = loggedData(*xPort, NodeSignal::Value, s.numLoggedSamples());
        const double c1 = loggedSlot(s, "Forks", "P1", "WaveVariable").back();
        if (c1 < 0.0) {
            for (double v : x) EXPECT_DOUBLE_EQ(v, -0.6) << "T=" << torque;
            EXPECT_DOUBLE_EQ(loggedSlot(s, "Forks", "P1", "AngularVelocity").back(), 0.0);
        } else {
            EXPECT_GT(x.back(), -0.6 + 0.01) << "T=" << torque;
        }
    }
}
