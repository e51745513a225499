#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type crank link as MechanicJLink but with two translational ports (Pm0, Pm1) that
// share the tip motion; their forces add. 5 unknowns, two damped Newton iterations.
class MechanicJLink2 : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedParts(double& p11, double& p21, double& p22) const;

    Port* mpPm0 = nullptr;
    Port* mpPm1 = nullptr;
    Port* mpPmr2 = nullptr;
    double *mpJL = nullptr, *mpBL = nullptr, *mpLink = nullptr, *mpX0 = nullptr,
           *mpThetaMin = nullptr, *mpThetaMax = nullptr;
    double *mpF0 = nullptr, *mpX0port = nullptr, *mpV0 = nullptr, *mpC0 = nullptr,
           *mpZc0 = nullptr, *mpMe0 = nullptr;
    double *mpF1 = nullptr, *mpX1 = nullptr, *mpV1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr,
           *mpMe1 = nullptr;
    double *mpT2 = nullptr, *mpA2 = nullptr, *mpW2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr,
           *mpJe2 = nullptr;

    double mW2 = 0.0, mTh2 = 0.0, mF0 = 0.0, mF1 = 0.0, mT2 = 0.0;
    double mXp0 = 0.0, mVp0 = 0.0, mMe0 = 0.0, mX1 = 0.0, mV1 = 0.0, mMe1 = 0.0, mJe2 = 0.0;
    double mD11 = 0.0, mD21 = 0.0, mD22 = 0.0;
    Delay mDelay22;

    Matrix mJac;
    Vec mF;
    Vec mX;
    EquationSystemSolver mSolver{5};
    bool mSingularReported = false;
};

} // namespace tlmhub
