#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type orifice with a combined laminar/turbulent discharge law from its
// geometry; solved with 2 Newton-Raphson iterations.
class HydraulicOrificeG : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_dE = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_dE = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpRho = nullptr, *mpVisc = nullptr, *mpAo = nullptr, *mpDh = nullptr;
    double *mpLo = nullptr, *mpCdt = nullptr, *mpDel = nullptr, *mpSf = nullptr;
    double *mpRo = nullptr, *mpDRL = nullptr, *mpCd = nullptr;

    // Unknowns carried between steps.
    double mQ2 = 0.0, mP1 = 0.0, mP2 = 0.0;
    double mDE1 = 0.0, mDE2 = 0.0;

    Matrix mJ{3, 3};
    Vec mF{3};
    Vec mX{3};
    EquationSystemSolver mSolver{3};
};

} // namespace tlmhub
