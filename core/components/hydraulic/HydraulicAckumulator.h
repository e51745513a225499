#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type gas-charged accumulator with inlet restriction; the oil filling is a
// state of charge xmp in [0, 1]. Solved with 2 Newton-Raphson iterations.
class HydraulicAckumulator : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_T = nullptr, *mpP1_dE = nullptr;
    double *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpV0 = nullptr, *mpKca = nullptr, *mpKappa = nullptr, *mpP0 = nullptr;
    double *mpVa = nullptr, *mpPa = nullptr, *mpXmp = nullptr, *mpVmp = nullptr;

    // Unknowns carried between steps.
    double mVmp = 0.0, mXmp = 0.0, mQ1 = 0.0, mPa = 0.0, mP1 = 0.0, mVa = 0.0;
    double mDE1 = 0.0;
    // One-step memory of the trapezoidal integration.
    double mD = 0.0;

    Matrix mJ{5, 5};
    Vec mF{5};
    Vec mX{5};
    EquationSystemSolver mSolver{5};
};

} // namespace tlmhub
