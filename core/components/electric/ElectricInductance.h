#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type ideal inductance (trapezoidal rule, generic 2-iteration Newton scheme).
class ElectricInductance : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPel1 = nullptr, *mpPel2 = nullptr;
    double* mpInduct = nullptr;
    double mInduct = 0.0;
    double mU1 = 0.0, mI1 = 0.0, mU2 = 0.0, mI2 = 0.0;
    double mDelayed1 = 0.0;
    EquationSystemSolver mSolver{3};
    Matrix mJ{3, 3};
    Vec mF{3}, mX{3};
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
    double *mpPel2_u = nullptr, *mpPel2_i = nullptr, *mpPel2_c = nullptr, *mpPel2_Zc = nullptr;
};

} // namespace tlmhub
