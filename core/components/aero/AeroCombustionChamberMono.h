#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// C-type monopropellant rocket combustion chamber with a convergent-divergent nozzle.
class AeroCombustionChamberMono : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpPa = nullptr, *mpVc = nullptr, *mpR = nullptr, *mpCv = nullptr, *mpVfuel = nullptr, *mpEthap = nullptr,
           *mpRhofuel = nullptr, *mpAs = nullptr, *mpMed = nullptr, *mpAlpha = nullptr;
    double *mpThrust = nullptr, *mpTc = nullptr, *mpRhogas = nullptr, *mpMdot = nullptr, *mpAe = nullptr,
           *mpPe = nullptr, *mpPc = nullptr, *mpTe = nullptr, *mpVe = nullptr, *mpPin = nullptr, *mpPout = nullptr;
    double mVc = 0.0, mR = 0.0, mCv = 0.0, mVfuel = 0.0, mEthap = 0.0, mRhofuel = 0.0, mAs = 0.0, mMed = 0.0,
           mAlpha = 0.0;
    double mC1 = 0.0, mC2 = 0.0, mZc1 = 0.0, mT1 = 0.0;
    double mRhogas = 0.0, mTc = 0.0, mMdot = 0.0, mPc = 0.0;
    double mThrust = 0.0, mAe = 0.0, mPe = 0.0, mTe = 0.0, mVe = 0.0, mPin = 0.0, mPout = 0.0;
    double mDelayed1 = 0.0;
    EquationSystemSolver mSolver{3};
    Matrix mJ{3, 3};
    Vec mF{3}, mX{3};
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_T = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
