#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// PID controller with output saturation and conditional-integration anti-windup
// (generated-solver type: exactly two Newton iterations, weights 1.0 and 0.67).
// The derivative term uses the supplied derivative dy of the measurement.
class SignalPID : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpYref = nullptr;
    double* mpY = nullptr;
    double* mpDy = nullptr;
    double* mpKp = nullptr;
    double* mpKI = nullptr;
    double* mpKd = nullptr;
    double* mpUmin = nullptr;
    double* mpUmax = nullptr;
    double* mpU = nullptr;
    double* mpIerr = nullptr;
    double* mpUI = nullptr;
    // Generated-solver pattern: two damped Newton iterations per step.
    Matrix mJ{3, 3};
    Vec mF{3};
    Vec mX{3};
    EquationSystemSolver mSolver{3};

    double mU = 0.0, mIerr = 0.0, mUI = 0.0;
    double mD = 0.0;   // delayed part of the integrator equation
};

} // namespace tlmhub
