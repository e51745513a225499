#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// PI controller with a lead compensator on the measured value, output saturation
// and conditional-integration anti-windup (generated-solver type, two Newton
// iterations with weights 1.0 and 0.67).
class SignalPIlead : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpYref = nullptr;
    double* mpKx = nullptr;
    double* mpY = nullptr;
    double* mpWa = nullptr;
    double* mpDa = nullptr;
    double* mpUmin = nullptr;
    double* mpUmax = nullptr;
    double* mpU = nullptr;
    double* mpErr = nullptr;
    double* mpIerr = nullptr;
    double* mpUI = nullptr;
    // Generated-solver pattern: two damped Newton iterations per step.
    Matrix mJ{4, 4};
    Vec mF{4};
    Vec mX{4};
    EquationSystemSolver mSolver{4};

    double mU = 0.0, mErr = 0.0, mIerr = 0.0, mUI = 0.0;
    double mD1 = 0.0, mD4 = 0.0;   // delayed parts (lead filter, integrator)
    void computeDelayedParts(double h, double y, double yref, double k1, double w11, double w21, double w22);
};

} // namespace tlmhub
