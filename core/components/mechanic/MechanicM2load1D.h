#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type two-mass load (m1 on Pm1, m2 on Pm2) joined by a limited-stroke relative
// coordinate with dry friction; Pm3 carries the relative motion. 9 unknowns, two damped
// Newton iterations per step.
class MechanicM2load1D : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedParts();

    Port *mpPm1 = nullptr, *mpPm2 = nullptr, *mpPm3 = nullptr;
    double *mpM1 = nullptr, *mpM2 = nullptr, *mpBL = nullptr, *mpFc = nullptr, *mpBfc = nullptr,
           *mpXpMin = nullptr, *mpXpMax = nullptr;
    double *mpVt = nullptr, *mpXt = nullptr;
    double *mpF1 = nullptr, *mpX1 = nullptr, *mpV1 = nullptr, *mpC1 = nullptr, *mpZc1 = nullptr,
           *mpMe1 = nullptr;
    double *mpF2 = nullptr, *mpX2 = nullptr, *mpV2 = nullptr, *mpC2 = nullptr, *mpZc2 = nullptr,
           *mpMe2 = nullptr;
    double *mpF3 = nullptr, *mpX3 = nullptr, *mpV3 = nullptr, *mpC3 = nullptr, *mpZc3 = nullptr,
           *mpMe3 = nullptr;

    // Unknowns [v1, v2, v3, x3, vt, xt, f1, f2, f3] and derived values.
    double mV1 = 0.0, mV2 = 0.0, mV3 = 0.0, mX3 = 0.0, mVt = 0.0, mXt = 0.0, mF1 = 0.0,
           mF2 = 0.0, mF3 = 0.0;
    double mX1 = 0.0, mX2 = 0.0, mMe1 = 0.0, mMe2 = 0.0, mMe3 = 0.0;
    // Delayed parts: first-order ones of the last step, and P42 from two steps back.
    double mP31 = 0.0, mP41 = 0.0, mP42 = 0.0, mP51 = 0.0, mP61 = 0.0;
    double mD31 = 0.0, mD41 = 0.0, mD42 = 0.0, mD51 = 0.0, mD61 = 0.0;
    Delay mDelay42;

    Matrix mJac;
    Vec mF;
    Vec mX;
    EquationSystemSolver mSolver{9};
    bool mSingularReported = false;
};

} // namespace tlmhub
