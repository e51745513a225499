#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Integrates velocities and time scaled by a time-compression factor and scales a
// mass flow. Generated-solver type with an identity Jacobian; initialisation
// already advances the state one step.
class SignalTimeAccelerator : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpTimecomp = nullptr;
    double* mpMassflow = nullptr;
    double* mpVxcg = nullptr;
    double* mpVycg = nullptr;
    double* mpTimeE = nullptr;
    double* mpMassflowE = nullptr;
    double* mpXcgE = nullptr;
    double* mpYcgE = nullptr;
    // Generated-solver pattern: two damped Newton iterations per step.
    Matrix mJ{3, 3};
    Vec mF{3};
    Vec mX{3};
    EquationSystemSolver mSolver{3};

    double mXcgE = 0.0, mYcgE = 0.0, mTimeE = 0.0, mMassflowE = 0.0;
    double mD1 = 0.0, mD2 = 0.0, mD3 = 0.0;
    void computeDelayedParts(double h, double tc, double vx, double vy);
};

} // namespace tlmhub
