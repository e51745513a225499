#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"

#include <vector>

namespace tlmhub {

// C-type long line with frequency dependent friction and visco-elastic wall
// damping (method of characteristics, cyclic delay memory, first order filters).
class HydraulicHose : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    static double rq(double& RL, double Q, double D, double L, double rho, double visc);

    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double *mpRho = nullptr, *mpVisc = nullptr, *mpD = nullptr, *mpL = nullptr;
    double mBetae = 1e9;
    double mWallVisc = 0.03;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;

    const double mKappa = 1.25;
    double mRw = 0.0, mNT = 0.0, mTN = 0.0, mZc0 = 0.0;
    double mBC0 = 0.0, mBC1 = 0.0, mAC1 = 0.0;
    double mRL1 = 0.0, mRL2 = 0.0, mRL1d = 0.0, mRL2d = 0.0;
    double mRQF1D = 0.0, mRQF2D = 0.0, mRQEF1D = 0.0, mRQEF2D = 0.0;
    FirstOrderTransferFunction mFilterC1F, mFilterC2F, mFilterC1F1, mFilterC2F1;

    // Cyclic characteristic memory, 1-based indices 1..NTMAX (slot 0 unused).
    int mNTIME = 1, mNTMAX = 1;
    std::vector<double> mC1i, mC2i;
};

} // namespace tlmhub
