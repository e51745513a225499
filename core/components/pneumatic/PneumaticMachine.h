#pragma once
#include "core/Component.h"
#include "core/components/pneumatic/PneumaticPortData.h"
#include "core/numerics/Delay.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type pneumatic displacement machine with shaft inertia, viscous friction and
// leakage; 8 unknowns solved with two damped Newton iterations per step.
class PneumaticMachine : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedParts(double& d11, double& d12, double& d21) const;

    Port *mpPp1 = nullptr, *mpPp2 = nullptr, *mpPmr1 = nullptr;
    double *mpDm = nullptr, *mpCim = nullptr, *mpBm = nullptr, *mpJm = nullptr, *mpR = nullptr, *mpCv = nullptr;
    PneumaticPortData mPp1, mPp2;
    double *mpPmr1_t = nullptr, *mpPmr1_a = nullptr, *mpPmr1_w = nullptr, *mpPmr1_c = nullptr, *mpPmr1_Zc = nullptr,
           *mpPmr1_J = nullptr;

    // Frozen inputs.
    double mDm = 0.0, mCim = 0.0, mBm = 0.0, mJm = 0.0, mR = 0.0, mCv = 0.0;
    // Unknowns (previous solution = next guess).
    double mTheta = 0.0, mW = 0.0, mQm2 = 0.0, mDE1 = 0.0, mDE2 = 0.0, mP1 = 0.0, mP2 = 0.0, mTorque = 0.0;
    double mEqInertia = 0.0;
    // Delayed parts: d11, d21 from the previous step, d12 from two steps back.
    double mD11 = 0.0, mD21 = 0.0, mD12Used = 0.0;
    Delay mD12Buffer;

    EquationSystemSolver mSolver{8};
    Matrix mJ{8, 8};
    Vec mF{8}, mX{8};
};

} // namespace tlmhub
