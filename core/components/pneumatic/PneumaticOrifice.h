#pragma once
#include "core/Component.h"
#include "core/components/pneumatic/PneumaticPortData.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type compressible (isentropic nozzle) orifice with choked-flow limit;
// 7 unknowns solved with two damped Newton iterations per step.
class PneumaticOrifice : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPp1 = nullptr, *mpPp2 = nullptr;
    double *mpA0 = nullptr, *mpCd = nullptr, *mpR = nullptr, *mpCv = nullptr, *mpEps = nullptr;
    double *mpQma = nullptr, *mpQmb = nullptr;
    PneumaticPortData mPp1, mPp2;

    // Frozen inputs.
    double mCd = 0.0, mR = 0.0, mCv = 0.0, mEps = 0.0;
    // Unknowns carried between steps (the previous solution is the next guess).
    double mQma = 0.0, mQmb = 0.0, mQm2 = 0.0, mDE1 = 0.0, mDE2 = 0.0, mP1 = 0.0, mP2 = 0.0;

    EquationSystemSolver mSolver{7};
    Matrix mJ{7, 7};
    Vec mF{7}, mX{7};
};

} // namespace tlmhub
