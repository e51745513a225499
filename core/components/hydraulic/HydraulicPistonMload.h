#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type generated double-acting piston with integrated load mass and end stops;
// the chambers are the connected C-elements. Two Newton iterations per step.
class HydraulicPistonMload : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void delayedParts(double& D11, double& D12, double& D21) const;

    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpPmp = nullptr;
    double* mp_A1 = nullptr;
    double* mp_A2 = nullptr;
    double* mp_SL = nullptr;
    double* mp_Cip = nullptr;
    double* mp_bp = nullptr;
    double* mp_mL = nullptr;
    double* mp_bL = nullptr;
    double* mp_fc = nullptr;
    double* mp_bfc = nullptr;
    double* mp_xmin = nullptr;
    double* mp_xmax = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpPmp_f = nullptr, *mpPmp_x = nullptr, *mpPmp_v = nullptr, *mpPmp_c = nullptr, *mpPmp_Zc = nullptr,
           *mpPmp_me = nullptr;

    // Member state persisting between steps (generated-component convention).
    double A1 = 0, A2 = 0, SL = 0, Cip = 0, bp = 0, mL = 0, bL = 0, fc = 0, bfc = 0, xmin = 0, xmax = 0;
    double xmp = 0, vmp = 0, fmp = 0, q1 = 0, q2 = 0, p1 = 0, p2 = 0;
    double c1 = 0, Zc1 = 0, c2 = 0, Zc2 = 0, cmp = 0, Zcmp = 0, eqMassmp = 0;
    double mD11 = 0, mD21 = 0;
    double mD12Used = 0;   // D12 from two steps back, used by the residuals
    double mD12Newest = 0; // D12 of the last completed step

    Matrix mJ{7, 7};
    Vec mF{7}, mX{7};
    EquationSystemSolver mSolver{7};
};

} // namespace tlmhub
