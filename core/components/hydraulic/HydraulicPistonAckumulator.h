#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type piston accumulator: a piston with mass, viscous friction and stroke
// limits separates oil and gas. Solved with 2 Newton-Raphson iterations.
class HydraulicPistonAckumulator : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void computeDelayedTerms(double& D11, double& D12, double& D21) const;

    Port* mpP1 = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_T = nullptr, *mpP1_dE = nullptr;
    double *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpAp = nullptr, *mpSL = nullptr, *mpBp = nullptr, *mpML = nullptr;
    double *mpKappa = nullptr, *mpP0 = nullptr;
    double *mpVa = nullptr, *mpPa = nullptr, *mpXmp = nullptr, *mpVmp = nullptr;

    double mXmp = 0.0, mVmp = 0.0, mQ1 = 0.0, mPa = 0.0, mP1 = 0.0, mVa = 0.0;
    double mDE1 = 0.0;
    // Memory terms of the second-order discretisation: D11/D21 one step back,
    // D12 two steps back (mD12Newest holds the last pushed value).
    double mDx1 = 0.0, mDx2 = 0.0, mDv = 0.0, mD12Newest = 0.0;

    Matrix mJ{5, 5};
    Vec mF{5};
    Vec mX{5};
    EquationSystemSolver mSolver{5};
};

} // namespace tlmhub
