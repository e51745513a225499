#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type gear with an inertia on port 2 and a torque-limited (slipping) port 1.
// Generated-model structure: 6 unknowns solved with two damped Newton iterations.
class MechanicGearClutch : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedParts();

    Port* mpPmr1 = nullptr;
    Port* mpPmr2 = nullptr;
    double *mpGearRatio = nullptr, *mpTmax = nullptr, *mpJg = nullptr, *mpBg = nullptr,
           *mpMyfric = nullptr, *mpWc = nullptr;
    double *mpT1 = nullptr, *mpA1 = nullptr, *mpW1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr,
           *mpJe1 = nullptr;
    double *mpT2 = nullptr, *mpA2 = nullptr, *mpW2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr,
           *mpJe2 = nullptr;

    // Frozen at initialize.
    double mJg = 1.0, mBg = 0.0;
    // Unknowns (persist between steps).
    double mW2 = 0.0, mTh2 = 0.0, mTh1 = 0.0, mT1 = 0.0, mW1 = 0.0, mT2 = 0.0;
    double mJe1 = 0.0, mJe2 = 0.0;
    double mD1 = 0.0, mD2 = 0.0, mD3 = 0.0;

    Matrix mJac;
    Vec mF;
    Vec mX;
    EquationSystemSolver mSolver{6};
    bool mSingularReported = false;
};

} // namespace tlmhub
