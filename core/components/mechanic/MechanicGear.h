#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type gear with its inertia, viscous friction and a torque-proportional gear friction
// lumped at the output shaft Pmr2; the input shaft Pmr1 turns at -gearRatio times its speed.
// Solved as Hopsan's generated code does: trapezoidal rule, two damped Newton steps.
class MechanicGear : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    // The parts of the discretised equations known from the previous step.
    void computeDelayedParts(double g);
    double frictionSign() const;

    Port *mpPmr1 = nullptr, *mpPmr2 = nullptr;
    double *mpGearRatio = nullptr, *mpJg = nullptr, *mpBg = nullptr, *mpMyfric = nullptr, *mpWc = nullptr;
    double mJg = 0.0, mBg = 0.0, mMyfric = 0.0, mWc = 0.0;
    double mW1 = 0.0, mW2 = 0.0, mTheta1 = 0.0, mTheta2 = 0.0, mT1 = 0.0, mT2 = 0.0;
    double mJeq1 = 0.0, mJeq2 = 0.0;
    double mDelayed1 = 0.0, mDelayed2 = 0.0, mDelayed3 = 0.0;
    EquationSystemSolver mSolver{5};
    Matrix mJ{5, 5};
    Vec mF{5}, mX{5};
    double *mpPmr1_w = nullptr, *mpPmr1_T = nullptr, *mpPmr1_a = nullptr, *mpPmr1_c = nullptr,
           *mpPmr1_Zc = nullptr, *mpPmr1_Je = nullptr;
    double *mpPmr2_w = nullptr, *mpPmr2_T = nullptr, *mpPmr2_a = nullptr, *mpPmr2_c = nullptr,
           *mpPmr2_Zc = nullptr, *mpPmr2_Je = nullptr;
};

} // namespace tlmhub
