#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type DC motor driving, through a gear and a screw, a link of length la whose angle is
// the rotational port Pmr1 (Hopsan display name "Linear Actuator With Link"). The link
// angle comes from a double integration of the acceleration and is held within
// [thetamin, thetamax]. 6 unknowns, two damped Newton iterations per step. Documented in
// docs/components/electric-mechanic-other.md, "ElectricMotorGearScrewLink".
class ElectricMotorGearScrewLink : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    // Scaled load torque A of (JL + g Jm) p^2 dw/dt = -A, its friction part and their
    // derivatives with respect to w, i2 and the port torque.
    struct Load {
        double a, fr, drive;          // A = drive + Bt w + fr, drive = p^2 (T - g Ke i2)
        double dAdw, dFrdw, dAdi, dAdT;
    };
    Load load(double g) const;
    // Sets mDTheta1 and mDW; returns the new second-order angle part (delayed once more).
    double computeDelayedParts(double g, const Load& l);

    Port *mpPel1 = nullptr, *mpPel2 = nullptr, *mpPmr1 = nullptr;
    double *mpGearRatio = nullptr, *mpKe = nullptr, *mpRa = nullptr, *mpTm0 = nullptr, *mpWc = nullptr,
           *mpBm = nullptr, *mpJm = nullptr, *mpMyg = nullptr, *mpMys = nullptr, *mpBL = nullptr,
           *mpJL = nullptr, *mpPitch = nullptr, *mpThetaMin = nullptr, *mpThetaMax = nullptr, *mpLa = nullptr;
    double *mpWm = nullptr, *mpTormg = nullptr, *mpPin = nullptr, *mpPout = nullptr;
    double *mpU1 = nullptr, *mpI1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr;
    double *mpU2 = nullptr, *mpI2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr;
    double *mpT = nullptr, *mpTheta = nullptr, *mpW = nullptr, *mpCm = nullptr, *mpZcm = nullptr,
           *mpJe = nullptr;

    // Parameters, read only in initialize() (as Hopsan's generated code does; only
    // gearRatio is read every step).
    double mKe = 0.0, mRa = 0.0, mTm0 = 0.0, mWc = 0.0, mBm = 0.0, mJm = 0.0, mMyg = 0.0,
           mMys = 0.0, mJL = 0.0, mPitch = 0.0, mThetaMin = 0.0, mThetaMax = 0.0, mLa = 0.0;

    // Unknowns [theta, w, i2, u1, u2, T], kept between steps, and derived values.
    double mTheta = 0.0, mW = 0.0, mI2 = 0.0, mU1 = 0.0, mU2 = 0.0, mT = 0.0;
    double mI1 = 0.0, mJe = 0.0;
    // Delayed parts: angle (first order, and second order through mDelayTheta2) and speed.
    double mDTheta1 = 0.0, mDTheta2 = 0.0, mDW = 0.0;
    Delay mDelayTheta2;

    Matrix mJac;
    Vec mEq;
    Vec mState;
    EquationSystemSolver mSolver{6};
    bool mSingularReported = false;
};

} // namespace tlmhub
