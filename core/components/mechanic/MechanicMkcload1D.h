#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type mass-spring-damper load with dry friction and stroke limits between two
// translational ports (spring to ground on x2). 4 unknowns, two damped Newton iterations.
class MechanicMkcload1D : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedParts(double& p11, double& p12, double& p21) const;

    Port* mpPm1 = nullptr;
    Port* mpPm2 = nullptr;
    double *mpML = nullptr, *mpBL = nullptr, *mpKL = nullptr, *mpFc = nullptr, *mpBfc = nullptr,
           *mpXMin = nullptr, *mpXMax = nullptr;
    double* mpFs = nullptr;
    double *mpF1 = nullptr, *mpX1 = nullptr, *mpV1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr,
           *mpMe1 = nullptr;
    double *mpF2 = nullptr, *mpX2 = nullptr, *mpV2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr,
           *mpMe2 = nullptr;

    double mX2 = 0.0, mV2 = 0.0, mF1 = 0.0, mF2 = 0.0;
    double mX1 = 0.0, mV1 = 0.0, mFs = 0.0, mMe1 = 0.0, mMe2 = 0.0;
    double mD11 = 0.0, mD12 = 0.0, mD21 = 0.0;
    Delay mDelay12;

    Matrix mJac;
    Vec mF;
    Vec mX;
    EquationSystemSolver mSolver{4};
    bool mSingularReported = false;
};

} // namespace tlmhub
