#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Low-pass filters |y1|, |y2|, |y3| (time constant thau) and raises s1 when a
// filtered value exceeds its threshold or sOn is set. Generated-solver type with
// an identity Jacobian; initialisation already advances the state one step, and
// s1 may take 0.33/0.67 for one step when it switches (reference behaviour).
class SignalStateMonitor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpY1 = nullptr;
    double* mpY2 = nullptr;
    double* mpY3 = nullptr;
    double* mpSOn = nullptr;
    double* mpY10 = nullptr;
    double* mpY20 = nullptr;
    double* mpY30 = nullptr;
    double* mpThau = nullptr;
    double* mpS1 = nullptr;
    double* mpY1f = nullptr;
    double* mpY2f = nullptr;
    double* mpY3f = nullptr;
    // Generated-solver pattern: two damped Newton iterations per step.
    Matrix mJ{4, 4};
    Vec mF{4};
    Vec mX{4};
    EquationSystemSolver mSolver{4};

    double mS1 = 0.0, mY1f = 0.0, mY2f = 0.0, mY3f = 0.0;
    double mD1 = 0.0, mD2 = 0.0, mD3 = 0.0;
    void computeDelayedParts(double h, double thau);
};

} // namespace tlmhub
