#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type averaged PWM switch (buck converter equivalent) with duty-dependent loss.
class ElectricPWMdceq : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPel1 = nullptr, *mpPel2 = nullptr;
    double *mpTfac = nullptr, *mpResist0 = nullptr, *mpResist1 = nullptr, *mpUmin = nullptr, *mpUmax = nullptr;
    double* mpUel10 = nullptr;
    double mResist0 = 0.0, mResist1 = 0.0, mUmin = 0.0, mUmax = 0.0;
    double mU2 = 0.0, mU10 = 0.0, mI1 = 0.0, mU1 = 0.0, mI2 = 0.0;
    EquationSystemSolver mSolver{5};
    Matrix mJ{5, 5};
    Vec mF{5}, mX{5};
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
    double *mpPel2_u = nullptr, *mpPel2_i = nullptr, *mpPel2_c = nullptr, *mpPel2_Zc = nullptr;
};

} // namespace tlmhub
