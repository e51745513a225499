#pragma once
#include "core/Component.h"
#include "core/components/aero/AeroVehicleTVC.h"

namespace tlmhub {

// C-type 6-DOF aircraft: main wing (ailerons, flaps), second lifting surface (elevators)
// and fin (rudder), on the common 6-DOF core.
class AeroAircraft6DOFS : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

    enum Frozen { k_afin, k_an1, k_an2, k_ap1, k_ap2, k_AR1, k_AR2, k_ARfin, k_Cd01, k_Cd02, k_Cd0b, k_Cd0fin, k_CLalpha1, k_CLalpha2, k_CLalphabh, k_CLalphabv, k_CLalphafin, k_CLde1, k_CLde2, k_CLde12, k_Cdide1, k_Cdide12, k_Cdide112, k_de10, k_de120, k_Cm01, k_Cmfs1, k_Cmde1, k_Cmde12, k_CLdefin, k_dah1, k_dah2, k_e1, k_e2, k_efin, k_awfin, k_awn1, k_awn2, k_awp1, k_awp2, k_gamma1, k_gamma2, k_hthrust0, k_ia1, k_ia2, k_Ix0, k_Ixz0, k_Iy0, k_Iz0, k_lambda1, k_lambda2, k_lambdafin, k_lc10, k_lc20, k_lc120, k_lcfin0, k_Med, k_rc10, k_rc20, k_rcfin0, k_S1, k_S20, k_Sbh0, k_Sbv0, k_Sfin0, k_xbach0, k_xbacv0, k_xbcge0, k_xcargo0, k_xfuel0, k_xw10, k_xw20, k_xwfin0, k_xeng0, k_yeng0, k_g0, k_kground, k_cground, kNumFrozen };

private:
    void explicitQuantities();
    void evalOutputs();
    void writeOutputs();

    static constexpr int kNumPorts = 7;
    Port* mpPorts[kNumPorts] = {};
    double* mpAngle[kNumPorts] = {};
    double* mpC[kNumPorts] = {};
    double* mpZc[kNumPorts] = {};
    double mCport[kNumPorts] = {};
    double mZcport[kNumPorts] = {};

    // Per-step inputs.
    double *mpThrustl = nullptr, *mpThrustr = nullptr, *mpDezthrustl = nullptr, *mpDezthrustr = nullptr,
           *mpDeythrustl = nullptr, *mpDeythrustr = nullptr, *mpMfuel = nullptr, *mpMcargo = nullptr,
           *mpRho = nullptr, *mpVturbx = nullptr, *mpVturby = nullptr, *mpVturbz = nullptr, *mpWturbx = nullptr,
           *mpWturby = nullptr, *mpWturbz = nullptr;
    // Inputs frozen at initialisation.
    double* mpFrozen[kNumFrozen] = {};
    double mFrozen[kNumFrozen] = {};

    // Outputs.
    double *mpXcg = nullptr, *mpYcg = nullptr, *mpZcg = nullptr, *mpVx = nullptr, *mpVy = nullptr, *mpVz = nullptr,
           *mpPsi = nullptr, *mpThetao = nullptr, *mpPhi = nullptr, *mpUb = nullptr, *mpVb = nullptr,
           *mpWb = nullptr, *mpPb = nullptr, *mpQb = nullptr, *mpRb = nullptr, *mpQ0 = nullptr, *mpQ1 = nullptr,
           *mpQ2 = nullptr, *mpQ3 = nullptr, *mpAlphaAttack = nullptr, *mpBetaSlip = nullptr,
           *mpAltitude = nullptr, *mpGfx = nullptr, *mpGfy = nullptr, *mpGfz = nullptr, *mpCL1 = nullptr,
           *mpCd1 = nullptr, *mpFax = nullptr, *mpFaz = nullptr;

    Aero6DofCore mCore;
    // Explicit-part results used by the outputs.
    double mAlpha = 0, mBeta = 0, mQpress = 0, mLsum = 0, mDsum = 0, mS2 = 0, mSbh = 0, mSfin = 0;
    double mLc1 = 0, mLc2 = 0, mLc12 = 0, mLcfin = 0, mKl = 0, mKr = 0, mCDi1 = 0, mCL1w = 0, mCL2w = 0;
    double mVx = 0, mVy = 0, mVz = 0, mPhi = 0, mThetao = 0, mPsi = 0, mCL1 = 0, mCd1 = 0;
};

} // namespace tlmhub
