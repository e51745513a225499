#pragma once
#include "core/Component.h"
#include "core/components/aero/AeroVehicleTVC.h"

namespace tlmhub {

// C-type 6-DOF aircraft with Mach-dependent lift slope and Oswald factor, transonic
// wave drag, wind in earth axes and coefficient increments; common 6-DOF core.
class AeroAircraft6DOFSS : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

    // All inputs, in registration order (every one is re-read each step).
    enum Input { k_deCD, k_deCY, k_deCL, k_deCl, k_deCm, k_deCn, k_thrustl, k_thrustr, k_dezthrustl, k_dezthrustr, k_deythrustl, k_deythrustr, k_Mfuel, k_Mcargo, k_rho, k_vM, k_vturbx, k_vturby, k_vturbz, k_wturbx, k_wturby, k_wturbz, k_afin, k_an1, k_an2, k_ap1, k_ap2, k_AR1, k_AR2, k_ARfin, k_Cd01, k_Cd02, k_Cd0b, k_Cd0fin, k_CdW0, k_CLalpha1, k_CLalpha2, k_CLalphabh, k_CLalphabv, k_CLalphafin, k_CLde1, k_CLde12, k_Cdide1, k_Cdide12, k_Cdide112, k_de10, k_de120, k_dM, k_Cm01, k_Cmfs1, k_Cmde1, k_Cmde12, k_CLdefin, k_Cydeelev, k_Cnbeta, k_dah1, k_dah2, k_en, k_e1, k_e2, k_efin, k_epsM, k_awfin, k_awn1, k_awn2, k_awp1, k_awp2, k_gamma1, k_gamma2, k_hthrust0, k_ia1, k_ia2, k_Ix0, k_Ixz0, k_Iy0, k_Iz0, k_lambda1, k_lambda2, k_lambdafin, k_lc10, k_lc20, k_lc120, k_lcfin0, k_Me, k_mac0, k_rc10, k_rc120, k_rc20, k_rcfin0, k_S1, k_S20, k_Sbh0, k_Sbv0, k_Sfin0, k_xbach0, k_xbacv0, k_xbcge0, k_xcargo0, k_xfuel0, k_xw10, k_xw20, k_xwfin0, k_xeng0, k_yeng0, k_g0, k_kground, k_cground, kNumInputs };

    enum Output { o_xcg, o_ycg, o_zcg, o_vx, o_vy, o_vz, o_Psi, o_Thetao, o_Phi, o_Ub, o_Vb, o_Wb, o_v, o_Pb, o_Qb, o_Rb, o_q0, o_q1, o_q2, o_q3, o_AlphaAttack, o_BetaSlip, o_altitude, o_gfx, o_gfy, o_gfz, o_CL1, o_Cd1, o_CL2, o_Cd2, o_CLtot, o_Cdtot, o_Lift1, o_Lift2, o_Fax, o_Faz, kNumOutputs };

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

    double* mpIn[kNumInputs] = {};
    double* mpOut[kNumOutputs] = {};
    double mOut[kNumOutputs] = {};

    Aero6DofCore mCore;
    // v and S2 persist between evaluations: the Mach terms use the previous v, and
    // b2 uses the previous S2 (0 before the first evaluation, as in Hopsan).
    double mV = 0.0, mS2 = 0.0;
    // Explicit-part results used by the outputs.
    double mAlpha = 0, mBeta = 0, mQpress = 0, mLsum = 0, mDsum = 0, mSbh = 0, mSfin = 0, mTn = 1;
    double mLc1 = 0, mLc2 = 0, mLc12 = 0, mLcfin = 0, mKl = 0, mKr = 0, mCDi1 = 0, mCL1w = 0;
    double mA1 = 0, mA2l = 0, mA2r = 0, mCLalpha2e = 0, mE2e = 0, mLift1 = 0, mLift2 = 0;
};

} // namespace tlmhub
