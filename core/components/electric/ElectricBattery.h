#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type battery with state of charge and a nonlinear open-circuit voltage curve.
class ElectricBattery : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPel1 = nullptr;
    double *mpCond = nullptr, *mpUnom = nullptr, *mpCapacity = nullptr, *mpKappa = nullptr, *mpE = nullptr;
    double *mpSoc = nullptr, *mpUbatt = nullptr;
    double mCond = 0.0, mUnom = 0.0, mCapacity = 0.0, mKappa = 0.0, mE = 0.0;
    double mSoc = 0.0, mI1 = 0.0, mUbatt = 0.0, mU1 = 0.0;
    double mDelayed1 = 0.0;
    EquationSystemSolver mSolver{4};
    Matrix mJ{4, 4};
    Vec mF{4}, mX{4};
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
};

} // namespace tlmhub
