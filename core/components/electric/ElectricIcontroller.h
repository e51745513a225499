#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type idealised current controller (DC/DC converter) with resistive loss.
class ElectricIcontroller : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double delayedPart() const;

    Port *mpPel1 = nullptr, *mpPel2 = nullptr;
    double *mpIref = nullptr, *mpResist = nullptr, *mpWf = nullptr, *mpUmin = nullptr, *mpImax = nullptr,
           *mpImin = nullptr, *mpUmax = nullptr;
    double mIref = 0.0, mResist = 0.0, mWf = 0.0, mUmin = 0.0, mUmax = 0.0;
    double mI1 = 0.0, mI2 = 0.0, mU1 = 0.0, mU2 = 0.0;
    double mDelayed1 = 0.0;
    EquationSystemSolver mSolver{4};
    Matrix mJ{4, 4};
    Vec mF{4}, mX{4};
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
    double *mpPel2_u = nullptr, *mpPel2_i = nullptr, *mpPel2_c = nullptr, *mpPel2_Zc = nullptr;
};

} // namespace tlmhub
