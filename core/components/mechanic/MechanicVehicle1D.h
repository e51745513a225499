#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type longitudinal vehicle of mass Mc driven through two wheel shafts, with
// aerodynamic drag and smoothed rolling resistance. 5 unknowns, two damped Newton
// iterations per step. Positive vehicle speed means negative shaft speed.
class MechanicVehicle1D : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeForces();
    void computeDelayedParts();

    Port *mpPmr1 = nullptr, *mpPmr2 = nullptr;
    double *mpMc = nullptr, *mpCfr = nullptr, *mpCdA = nullptr, *mpRwheel = nullptr,
           *mpRho = nullptr;
    double *mpVc = nullptr, *mpXc = nullptr, *mpFd = nullptr, *mpFr = nullptr;
    double *mpT1 = nullptr, *mpA1 = nullptr, *mpW1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr,
           *mpJe1 = nullptr;
    double *mpT2 = nullptr, *mpA2 = nullptr, *mpW2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr,
           *mpJe2 = nullptr;

    double mVc = 0.0, mXc = 0.0, mTh1 = 0.0, mT1 = 0.0, mT2 = 0.0;
    double mW1 = 0.0, mW2 = 0.0, mTh2 = 0.0, mJe1 = 0.0, mJe2 = 0.0, mFr = 0.0;
    double mFd = 0.0, mFre = 0.0;
    double mD1 = 0.0, mD2 = 0.0, mD3 = 0.0;

    Matrix mJac;
    Vec mF;
    Vec mX;
    EquationSystemSolver mSolver{5};
    bool mSingularReported = false;
};

} // namespace tlmhub
