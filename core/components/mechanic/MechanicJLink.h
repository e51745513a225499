#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type crank link of inertia JL: rotation at Pmr2 drives the translational port Pm1
// with x = x0 - link*sin(theta); angle limited to [thetamin, thetamax].
// Generated-model structure: 4 unknowns, two damped Newton iterations per step.
class MechanicJLink : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedParts(double& p11, double& p21, double& p22) const;

    Port* mpPm1 = nullptr;
    Port* mpPmr2 = nullptr;
    double *mpJL = nullptr, *mpBL = nullptr, *mpLink = nullptr, *mpX0 = nullptr,
           *mpTheta0 = nullptr, *mpThetaMin = nullptr, *mpThetaMax = nullptr;
    double *mpF1 = nullptr, *mpX1 = nullptr, *mpV1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr,
           *mpMe1 = nullptr;
    double *mpT2 = nullptr, *mpA2 = nullptr, *mpW2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr,
           *mpJe2 = nullptr;

    // Unknowns and derived values (persist between steps).
    double mW2 = 0.0, mTh2 = 0.0, mF1 = 0.0, mT2 = 0.0;
    double mX1 = 0.0, mV1 = 0.0, mMe1 = 0.0, mJe2 = 0.0;
    double mD11 = 0.0, mD21 = 0.0, mD22 = 0.0;
    Delay mDelay22;

    Matrix mJac;
    Vec mF;
    Vec mX;
    EquationSystemSolver mSolver{4};
    bool mSingularReported = false;
};

} // namespace tlmhub
