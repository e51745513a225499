#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type permanent-magnet DC motor with rotor inertia and smoothed Coulomb friction.
class ElectricMotor : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedParts();

    Port *mpPel1 = nullptr, *mpPel2 = nullptr, *mpPmr1 = nullptr;
    double *mpKe = nullptr, *mpRa = nullptr, *mpTm0 = nullptr, *mpWc = nullptr, *mpBm = nullptr, *mpJm = nullptr;
    double *mpTormg = nullptr, *mpPin = nullptr, *mpPout = nullptr;
    double mKe = 0.0, mRa = 0.0, mTm0 = 0.0, mWc = 0.0, mBm = 0.0, mJm = 0.0;
    double mW = 0.0, mTheta = 0.0, mI2 = 0.0, mU1 = 0.0, mU2 = 0.0, mT = 0.0, mI1 = 0.0, mJeq = 0.0;
    double mTormg = 0.0, mPin = 0.0, mPout = 0.0;
    double mDelayed1 = 0.0, mDelayed2 = 0.0;
    EquationSystemSolver mSolver{6};
    Matrix mJ{6, 6};
    Vec mF{6}, mX{6};
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
    double *mpPel2_u = nullptr, *mpPel2_i = nullptr, *mpPel2_c = nullptr, *mpPel2_Zc = nullptr;
    double *mpPmr1_w = nullptr, *mpPmr1_T = nullptr, *mpPmr1_a = nullptr, *mpPmr1_c = nullptr,
           *mpPmr1_Zc = nullptr, *mpPmr1_Je = nullptr;
};

} // namespace tlmhub
