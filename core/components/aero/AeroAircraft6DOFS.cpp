#include "core/components/aero/AeroAircraft6DOFS.h"

#include "core/ComponentFactory.h"
#include "core/components/aero/AircraftControlSurfaces.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

namespace {
using enum aircraft::ControlSurface;

struct FrozenInput {
    const char* name;
    const char* unit;
    double defaultValue;
};
// Order matches AeroAircraft6DOFS::Frozen.
const FrozenInput kFrozenInputs[AeroAircraft6DOFS::kNumFrozen] = {
    {"afin", "", 0.3},
    {"an1", "", 0.6},
    {"an2", "", 0.6},
    {"ap1", "", 0.9},
    {"ap2", "", 0.7},
    {"AR1", "", 2.24},
    {"AR2", "", 2.2},
    {"ARfin", "", 0.58},
    {"Cd01", "", 0.0045},
    {"Cd02", "", 0.0045},
    {"Cd0b", "", 0.004},
    {"Cd0fin", "", 0.0045},
    {"CLalpha1", "", 2.1},
    {"CLalpha2", "", 2.2},
    {"CLalphabh", "", 2.0},
    {"CLalphabv", "", 2.0},
    {"CLalphafin", "", 0.8},
    {"CLde1", "", 0.1},
    {"CLde2", "", 0.515},
    {"CLde12", "", 0.2},
    {"Cdide1", "", 0.0},
    {"Cdide12", "", 0.0},
    {"Cdide112", "", 0.0},
    {"de10", "", 0.01},
    {"de120", "", 0.01},
    {"Cm01", "", -0.1},
    {"Cmfs1", "", -0.5},
    {"Cmde1", "", 0.02},
    {"Cmde12", "", 0.1},
    {"CLdefin", "", 0.0827084},
    {"dah1", "", 1.0},
    {"dah2", "", 0.6},
    {"e1", "", 0.95},
    {"e2", "", 0.95},
    {"efin", "", 0.95},
    {"awfin", "", 0.2},
    {"awn1", "", 0.2},
    {"awn2", "", 0.2},
    {"awp1", "", 0.2},
    {"awp2", "", 0.2},
    {"gamma1", "", -0.0872665},
    {"gamma2", "", -0.0872665},
    {"hthrust0", "", 0.0},
    {"ia1", "", 0.0},
    {"ia2", "", 0.02},
    {"Ix0", "", 0.0022},
    {"Ixz0", "", 0.001},
    {"Iy0", "", 0.06},
    {"Iz0", "", 0.08},
    {"lambda1", "", 0.436332},
    {"lambda2", "", 0.436332},
    {"lambdafin", "", 0.785398},
    {"lc10", "", 0.005},
    {"lc20", "", 0.005},
    {"lc120", "", 0.005},
    {"lcfin0", "", 0.005},
    {"Med", "kg", 5000.0},
    {"rc10", "", 0.25},
    {"rc20", "", 0.15},
    {"rcfin0", "", 0.1},
    {"S1", "m2", 40.0},
    {"S20", "", 0.5},
    {"Sbh0", "", 0.2},
    {"Sbv0", "", 0.2},
    {"Sfin0", "", 0.17},
    {"xbach0", "", 2.0},
    {"xbacv0", "", 2.0},
    {"xbcge0", "", 1.4},
    {"xcargo0", "", 1.4},
    {"xfuel0", "", 1.4},
    {"xw10", "", 1.55},
    {"xw20", "", 2.6},
    {"xwfin0", "", 2.6},
    {"xeng0", "", 2.6},
    {"yeng0", "", 0.0},
    {"g0", "m/s2", 9.81},
    {"kground", "N/m", 10000.0},
    {"cground", "Ns/m", 1000.0},
};
} // namespace

void AeroAircraft6DOFS::configure()
{
    for (int i = 0; i < kNumPorts; ++i) { mpPorts[i] = addPowerPort(aircraft::kControlSurfacePortNames[i], NodeType::MechanicRotational); }

    addInputVariable("thrustl", "Thrust left engine", "N", 0.0, &mpThrustl);
    addInputVariable("thrustr", "Thrust right engine", "N", 0.0, &mpThrustr);
    addInputVariable("dezthrustl", "Thrust angle z left", "rad", 0.0, &mpDezthrustl);
    addInputVariable("dezthrustr", "Thrust angle z right", "rad", 0.0, &mpDezthrustr);
    addInputVariable("deythrustl", "Thrust angle y left", "rad", 0.0, &mpDeythrustl);
    addInputVariable("deythrustr", "Thrust angle y right", "rad", 0.0, &mpDeythrustr);
    addInputVariable("Mfuel", "Fuel mass", "kg", 0.0, &mpMfuel);
    addInputVariable("Mcargo", "Cargo mass", "kg", 0.0, &mpMcargo);
    addInputVariable("rho", "Air density", "kg/m3", 1.25, &mpRho);
    addInputVariable("vturbx", "Turbulence velocity x", "m/s", 0.0, &mpVturbx);
    addInputVariable("vturby", "Turbulence velocity y", "m/s", 0.0, &mpVturby);
    addInputVariable("vturbz", "Turbulence velocity z", "m/s", 0.0, &mpVturbz);
    addInputVariable("wturbx", "Turbulence rotation x", "rad/s", 0.0, &mpWturbx);
    addInputVariable("wturby", "Turbulence rotation y", "rad/s", 0.0, &mpWturby);
    addInputVariable("wturbz", "Turbulence rotation z", "rad/s", 0.0, &mpWturbz);
    for (int i = 0; i < kNumFrozen; ++i) {
        addInputVariable(kFrozenInputs[i].name, kFrozenInputs[i].name, kFrozenInputs[i].unit,
                         kFrozenInputs[i].defaultValue, &mpFrozen[i]);
        // Frozen at initialize(): a new value needs a new start.
        setLiveChangeable({kFrozenInputs[i].name}, false);
    }

    addOutputVariable("xcg", "Position x (earth)", "m", 0.0, &mpXcg);
    addOutputVariable("ycg", "Position y (earth)", "m", 0.0, &mpYcg);
    addOutputVariable("zcg", "Position z (earth, down)", "m", 0.0, &mpZcg);
    addOutputVariable("vx", "Velocity x (earth)", "m/s", 0.0, &mpVx);
    addOutputVariable("vy", "Velocity y (earth)", "m/s", 0.0, &mpVy);
    addOutputVariable("vz", "Velocity z (earth)", "m/s", 0.0, &mpVz);
    addOutputVariable("Psi", "Heading", "rad", 0.0, &mpPsi);
    addOutputVariable("Thetao", "Pitch", "rad", 0.0, &mpThetao);
    addOutputVariable("Phi", "Roll", "rad", 0.0, &mpPhi);
    addOutputVariable("Ub", "Body velocity x", "m/s", 100.0, &mpUb);
    addOutputVariable("Vb", "Body velocity y", "m/s", 0.0, &mpVb);
    addOutputVariable("Wb", "Body velocity z", "m/s", 0.0, &mpWb);
    addOutputVariable("Pb", "Body roll rate", "rad/s", 0.0, &mpPb);
    addOutputVariable("Qb", "Body pitch rate", "rad/s", 0.0, &mpQb);
    addOutputVariable("Rb", "Body yaw rate", "rad/s", 0.0, &mpRb);
    addOutputVariable("q0", "Quaternion 0", "", 0.0, &mpQ0);
    addOutputVariable("q1", "Quaternion 1", "", 0.0, &mpQ1);
    addOutputVariable("q2", "Quaternion 2", "", 0.0, &mpQ2);
    addOutputVariable("q3", "Quaternion 3", "", 0.0, &mpQ3);
    addOutputVariable("AlphaAttack", "Angle of attack", "rad", 0.0, &mpAlphaAttack);
    addOutputVariable("BetaSlip", "Side slip angle", "rad", 0.0, &mpBetaSlip);
    addOutputVariable("altitude", "Altitude", "m", 0.0, &mpAltitude);
    addOutputVariable("gfx", "Acceleration x (body)", "m/s2", 0.0, &mpGfx);
    addOutputVariable("gfy", "Acceleration y (body)", "m/s2", 0.0, &mpGfy);
    addOutputVariable("gfz", "Acceleration z (body)", "m/s2", 0.0, &mpGfz);
    addOutputVariable("CL1", "Lift coefficient", "", 0.0, &mpCL1);
    addOutputVariable("Cd1", "Drag coefficient", "", 0.0, &mpCd1);
    addOutputVariable("Fax", "Aerodynamic force x", "N", 0.0, &mpFax);
    addOutputVariable("Faz", "Aerodynamic force z", "N", 0.0, &mpFaz);
}

void AeroAircraft6DOFS::explicitQuantities()
{
    [[maybe_unused]] const double afin = mFrozen[k_afin];
    [[maybe_unused]] const double an1 = mFrozen[k_an1];
    [[maybe_unused]] const double an2 = mFrozen[k_an2];
    [[maybe_unused]] const double ap1 = mFrozen[k_ap1];
    [[maybe_unused]] const double ap2 = mFrozen[k_ap2];
    [[maybe_unused]] const double AR1 = mFrozen[k_AR1];
    [[maybe_unused]] const double AR2 = mFrozen[k_AR2];
    [[maybe_unused]] const double ARfin = mFrozen[k_ARfin];
    [[maybe_unused]] const double Cd01 = mFrozen[k_Cd01];
    [[maybe_unused]] const double Cd02 = mFrozen[k_Cd02];
    [[maybe_unused]] const double Cd0b = mFrozen[k_Cd0b];
    [[maybe_unused]] const double Cd0fin = mFrozen[k_Cd0fin];
    [[maybe_unused]] const double CLalpha1 = mFrozen[k_CLalpha1];
    [[maybe_unused]] const double CLalpha2 = mFrozen[k_CLalpha2];
    [[maybe_unused]] const double CLalphabh = mFrozen[k_CLalphabh];
    [[maybe_unused]] const double CLalphabv = mFrozen[k_CLalphabv];
    [[maybe_unused]] const double CLalphafin = mFrozen[k_CLalphafin];
    [[maybe_unused]] const double CLde1 = mFrozen[k_CLde1];
    [[maybe_unused]] const double CLde2 = mFrozen[k_CLde2];
    [[maybe_unused]] const double CLde12 = mFrozen[k_CLde12];
    [[maybe_unused]] const double Cdide1 = mFrozen[k_Cdide1];
    [[maybe_unused]] const double Cdide12 = mFrozen[k_Cdide12];
    [[maybe_unused]] const double Cdide112 = mFrozen[k_Cdide112];
    [[maybe_unused]] const double de10 = mFrozen[k_de10];
    [[maybe_unused]] const double de120 = mFrozen[k_de120];
    [[maybe_unused]] const double Cm01 = mFrozen[k_Cm01];
    [[maybe_unused]] const double Cmfs1 = mFrozen[k_Cmfs1];
    [[maybe_unused]] const double Cmde1 = mFrozen[k_Cmde1];
    [[maybe_unused]] const double Cmde12 = mFrozen[k_Cmde12];
    [[maybe_unused]] const double CLdefin = mFrozen[k_CLdefin];
    [[maybe_unused]] const double dah1 = mFrozen[k_dah1];
    [[maybe_unused]] const double dah2 = mFrozen[k_dah2];
    [[maybe_unused]] const double e1 = mFrozen[k_e1];
    [[maybe_unused]] const double e2 = mFrozen[k_e2];
    [[maybe_unused]] const double efin = mFrozen[k_efin];
    [[maybe_unused]] const double awfin = mFrozen[k_awfin];
    [[maybe_unused]] const double awn1 = mFrozen[k_awn1];
    [[maybe_unused]] const double awn2 = mFrozen[k_awn2];
    [[maybe_unused]] const double awp1 = mFrozen[k_awp1];
    [[maybe_unused]] const double awp2 = mFrozen[k_awp2];
    [[maybe_unused]] const double gamma1 = mFrozen[k_gamma1];
    [[maybe_unused]] const double gamma2 = mFrozen[k_gamma2];
    [[maybe_unused]] const double hthrust0 = mFrozen[k_hthrust0];
    [[maybe_unused]] const double ia1 = mFrozen[k_ia1];
    [[maybe_unused]] const double ia2 = mFrozen[k_ia2];
    [[maybe_unused]] const double Ix0 = mFrozen[k_Ix0];
    [[maybe_unused]] const double Ixz0 = mFrozen[k_Ixz0];
    [[maybe_unused]] const double Iy0 = mFrozen[k_Iy0];
    [[maybe_unused]] const double Iz0 = mFrozen[k_Iz0];
    [[maybe_unused]] const double lambda1 = mFrozen[k_lambda1];
    [[maybe_unused]] const double lambda2 = mFrozen[k_lambda2];
    [[maybe_unused]] const double lambdafin = mFrozen[k_lambdafin];
    [[maybe_unused]] const double lc10 = mFrozen[k_lc10];
    [[maybe_unused]] const double lc20 = mFrozen[k_lc20];
    [[maybe_unused]] const double lc120 = mFrozen[k_lc120];
    [[maybe_unused]] const double lcfin0 = mFrozen[k_lcfin0];
    [[maybe_unused]] const double Med = mFrozen[k_Med];
    [[maybe_unused]] const double rc10 = mFrozen[k_rc10];
    [[maybe_unused]] const double rc20 = mFrozen[k_rc20];
    [[maybe_unused]] const double rcfin0 = mFrozen[k_rcfin0];
    [[maybe_unused]] const double S1 = mFrozen[k_S1];
    [[maybe_unused]] const double S20 = mFrozen[k_S20];
    [[maybe_unused]] const double Sbh0 = mFrozen[k_Sbh0];
    [[maybe_unused]] const double Sbv0 = mFrozen[k_Sbv0];
    [[maybe_unused]] const double Sfin0 = mFrozen[k_Sfin0];
    [[maybe_unused]] const double xbach0 = mFrozen[k_xbach0];
    [[maybe_unused]] const double xbacv0 = mFrozen[k_xbacv0];
    [[maybe_unused]] const double xbcge0 = mFrozen[k_xbcge0];
    [[maybe_unused]] const double xcargo0 = mFrozen[k_xcargo0];
    [[maybe_unused]] const double xfuel0 = mFrozen[k_xfuel0];
    [[maybe_unused]] const double xw10 = mFrozen[k_xw10];
    [[maybe_unused]] const double xw20 = mFrozen[k_xw20];
    [[maybe_unused]] const double xwfin0 = mFrozen[k_xwfin0];
    [[maybe_unused]] const double xeng0 = mFrozen[k_xeng0];
    [[maybe_unused]] const double yeng0 = mFrozen[k_yeng0];
    [[maybe_unused]] const double g0 = mFrozen[k_g0];
    [[maybe_unused]] const double kground = mFrozen[k_kground];
    [[maybe_unused]] const double cground = mFrozen[k_cground];
    Aero6DofCore& st = mCore;
    const double thal1 = *mpAngle[al1], thar1 = *mpAngle[ar1], thal12 = *mpAngle[al12], thar12 = *mpAngle[ar12];
    const double thal2 = *mpAngle[al2], thar2 = *mpAngle[ar2], thfin = *mpAngle[fin];
    const double thrustl = *mpThrustl, thrustr = *mpThrustr;
    const double dezthrustl = *mpDezthrustl, dezthrustr = *mpDezthrustr;
    const double deythrustl = *mpDeythrustl, deythrustr = *mpDeythrustr;
    const double Mfuel = *mpMfuel, Mcargo = *mpMcargo, rho = *mpRho;
    const double vturbx = *mpVturbx, vturby = *mpVturby, vturbz = *mpVturbz;
    const double wturbx = *mpWturbx, wturby = *mpWturby, wturbz = *mpWturbz;

    const double s = std::sqrt(S1 / AR1);
    const double b = std::sqrt(AR1 * S1);
    st.Ix = AR1 * Ix0 * Med * S1;
    st.Ixz = AR1 * Ixz0 * Med * S1;
    st.Iy = Iy0 * Med * S1;
    st.Iz = Iz0 * Med * S1 / AR1;
    mLc1 = lc10 * s;
    mLc2 = lc20 * s;
    mLc12 = lc120 * s;
    mLcfin = lcfin0 * s;
    const double rc1 = rc10 * b;
    const double rc2 = rc20 * b;
    const double S2 = S1 * S20;
    const double Sbh = S1 * Sbh0;
    const double Sbv = S1 * Sbv0;
    const double Sfin = S1 * Sfin0;
    mS2 = S2;
    mSbh = Sbh;
    mSfin = Sfin;
    const double xbcge = s * xbcge0;
    const double xcargo = s * xcargo0;
    const double xfuel = s * xfuel0;
    const double xw1 = s * xw10;
    const double xw2 = s * xw20;
    const double xwfin = s * xwfin0;
    const double xeng = b * xeng0;
    const double yeng = b * yeng0;

    const double Uw = st.Ub + vturbx, Vw = st.Vb + vturby, Ww = st.Wb + vturbz;
    const double v = std::sqrt(0.0001 + Uw * Uw + Vw * Vw + Ww * Ww);
    const double Alpha = Atan2L(Ww, 0.0001 + st.Ub + vturbx);
    const double qpress = rho * (v * v) / 2.0;
    const double Beta = Atan2L(Vw, std::sqrt(0.0001 + Uw * Uw + Ww * Ww));
    mAlpha = Alpha;
    mBeta = Beta;
    mQpress = qpress;
    const double mass = Mcargo + Med + Mfuel;
    const double xbcg = (Med * xbcge + Mcargo * xcargo + Mfuel * xfuel) / mass;
    const double cosA = std::cos(Alpha), sinA = std::sin(Alpha), cosB = std::cos(Beta), sinB = std::sin(Beta);

    const double a1 = Alpha * dah1 - ia1;
    mKl = Cdide1 * ((thal1 - de10) * (thal1 - de10)) - Cdide112 * (thal1 - de10) * (thal12 - de120)
          + Cdide12 * ((thal12 - de120) * (thal12 - de120));
    mKr = Cdide1 * ((thar1 - de10) * (thar1 - de10)) - Cdide112 * (thar1 - de10) * (thar12 - de120)
          + Cdide12 * ((thar12 - de120) * (thar12 - de120));
    mCDi1 = CDragInd(a1, AR1, e1, CLalpha1, ap1, an1, awp1, awn1);
    mCL1w = CLift(a1, CLalpha1, ap1, an1, awp1, awn1);
    mCL2w = CLift(Alpha * dah2 - ia2, CLalpha2, ap2, an2, awp2, awn2);
    const double Dragl1 = qpress * S1 * (Cd01 / 2.0 + mKl + mCDi1 / 2.0);
    const double Dragr1 = qpress * S1 * (Cd01 / 2.0 + mKr + mCDi1 / 2.0);
    const double Liftl1 = qpress * S1 * (CLde1 * thal1 + CLde12 * thal12 + mCL1w / 2.0);
    const double Liftr1 = qpress * S1 * (CLde1 * thar1 + CLde12 * thar12 + mCL1w / 2.0);
    const double Dragl2 =
        qpress * S2 * (Cd02 / 2.0 + CDragInd(Alpha * dah2 - ia2 + thal2, AR2, e2, CLalpha2, ap2, an2, awp2, awn2) / 2.0);
    const double Dragr2 =
        qpress * S2 * (Cd02 / 2.0 + CDragInd(Alpha * dah2 - ia2 + thar2, AR2, e2, CLalpha2, ap2, an2, awp2, awn2) / 2.0);
    const double Liftl2 = qpress * S2 * (CLde2 * thal2 + mCL2w / 2.0);
    const double Liftr2 = qpress * S2 * (CLde2 * thar2 + mCL2w / 2.0);
    const double Liftb = CLalphabh * qpress * Sbh * sinA;
    const double Dragb = Cd0b * qpress * Sbh;
    const double Cfin =
        qpress * Sfin * CLift(-Beta - CLdefin * thfin / CLalphafin, CLalphafin, afin, afin, awfin, awfin);
    const double Dragfin = Cd0fin * qpress * Sfin;
    const double Mdvtheta = CLalpha2 * qpress * S2 * ((xw2 - xbcg) * (xw2 - xbcg)) / (0.1 + v);
    const double Mdvpsi = CLalphafin * qpress * Sfin * ((xwfin - xbcg) * (xwfin - xbcg)) / (0.1 + v);
    const double Dsum = Dragb + Dragfin + Dragl1 + Dragl2 + Dragr1 + Dragr2;
    const double Lsum = Liftb + Liftl1 + Liftl2 + Liftr1 + Liftr2;
    const double Y = -Cfin + CLalphabv * qpress * Sbv * sinB;
    mDsum = Dsum;
    mLsum = Lsum;
    const double H = onPositive(st.zcg);

    // Thrust terms reproduced as in Hopsan (thrustl twice, dezthrustr for both engines).
    st.Fx = -Dsum * cosA * cosB + Lsum * sinA - cosA * sinB * Y
            + thrustl * std::cos(deythrustl) * std::cos(dezthrustr) + thrustl * std::cos(deythrustr) * std::cos(dezthrustr);
    st.Fy = -Dsum * sinB + cosB * Y - thrustl * std::cos(dezthrustr) * std::sin(deythrustl)
            - thrustl * std::cos(dezthrustr) * std::sin(deythrustr);
    st.Fz = -Lsum * cosA - Dsum * cosB * sinA - sinA * sinB * Y - kground * st.zcg * H
            - thrustl * std::cos(deythrustl) * std::sin(dezthrustr) - thrustl * std::cos(deythrustr) * std::sin(dezthrustr);
    st.Lb = -0.12249999999999998 * qpress * (AR1 * CLalpha1 * (S1 * S1) + AR2 * CLalpha2 * (S2 * S2))
                * (st.Pb + wturbx) / (0.1 + v)
            + rc1 * rc2 * ((Liftl1 - Liftr1) * cosA - (Dragl1 - Dragr1) * sinA)
            + rc2 * ((Liftl2 - Liftr2) * cosA - (Dragl2 - Dragr2) * sinA)
            + yeng * (thrustl * std::cos(deythrustl) * std::sin(dezthrustl)
                      - thrustr * std::cos(deythrustr) * std::sin(dezthrustr));
    st.Mb = -Mdvtheta * (st.Qb + wturby)
            + qpress * S1
                  * (-Cmde1 * (thal1 + thar1) - Cmde12 * (thal12 + thar12)
                     + CMoment(a1, Cm01, Cmfs1, ap1, an1, awp1, awn1))
            + (xbcg - xw1) * ((Liftl1 + Liftr1) * cosA + (Dragl1 + Dragr1) * sinA)
            + (xbcg - xw2) * ((Liftl2 + Liftr2) * cosA - (Dragl2 + Dragr2) * sinA)
            + (xbcg - xeng) * (thrustl * std::cos(deythrustl) * std::sin(dezthrustl)
                               + thrustr * std::cos(deythrustr) * std::sin(dezthrustr));
    st.Nb = -Mdvpsi * (st.Rb + wturbz) - Cfin * (xwfin - xbcg)
            + rc1 * ((Dragr1 - Dragl1) * cosA + (Liftr1 - Liftl1) * sinA)
            + rc2 * ((Dragr2 - Dragl2) * cosA + (Liftr2 - Liftl2) * sinA)
            + (xbcg - xeng) * (thrustl * std::cos(dezthrustl) * std::sin(deythrustl)
                               + thrustr * std::cos(dezthrustr) * std::sin(deythrustr));
    st.m = mass;
    st.g = g0;
    st.k = kground;
}

void AeroAircraft6DOFS::evalOutputs()
{
    [[maybe_unused]] const double afin = mFrozen[k_afin];
    [[maybe_unused]] const double an1 = mFrozen[k_an1];
    [[maybe_unused]] const double an2 = mFrozen[k_an2];
    [[maybe_unused]] const double ap1 = mFrozen[k_ap1];
    [[maybe_unused]] const double ap2 = mFrozen[k_ap2];
    [[maybe_unused]] const double AR1 = mFrozen[k_AR1];
    [[maybe_unused]] const double AR2 = mFrozen[k_AR2];
    [[maybe_unused]] const double ARfin = mFrozen[k_ARfin];
    [[maybe_unused]] const double Cd01 = mFrozen[k_Cd01];
    [[maybe_unused]] const double Cd02 = mFrozen[k_Cd02];
    [[maybe_unused]] const double Cd0b = mFrozen[k_Cd0b];
    [[maybe_unused]] const double Cd0fin = mFrozen[k_Cd0fin];
    [[maybe_unused]] const double CLalpha1 = mFrozen[k_CLalpha1];
    [[maybe_unused]] const double CLalpha2 = mFrozen[k_CLalpha2];
    [[maybe_unused]] const double CLalphabh = mFrozen[k_CLalphabh];
    [[maybe_unused]] const double CLalphabv = mFrozen[k_CLalphabv];
    [[maybe_unused]] const double CLalphafin = mFrozen[k_CLalphafin];
    [[maybe_unused]] const double CLde1 = mFrozen[k_CLde1];
    [[maybe_unused]] const double CLde2 = mFrozen[k_CLde2];
    [[maybe_unused]] const double CLde12 = mFrozen[k_CLde12];
    [[maybe_unused]] const double Cdide1 = mFrozen[k_Cdide1];
    [[maybe_unused]] const double Cdide12 = mFrozen[k_Cdide12];
    [[maybe_unused]] const double Cdide112 = mFrozen[k_Cdide112];
    [[maybe_unused]] const double de10 = mFrozen[k_de10];
    [[maybe_unused]] const double de120 = mFrozen[k_de120];
    [[maybe_unused]] const double Cm01 = mFrozen[k_Cm01];
    [[maybe_unused]] const double Cmfs1 = mFrozen[k_Cmfs1];
    [[maybe_unused]] const double Cmde1 = mFrozen[k_Cmde1];
    [[maybe_unused]] const double Cmde12 = mFrozen[k_Cmde12];
    [[maybe_unused]] const double CLdefin = mFrozen[k_CLdefin];
    [[maybe_unused]] const double dah1 = mFrozen[k_dah1];
    [[maybe_unused]] const double dah2 = mFrozen[k_dah2];
    [[maybe_unused]] const double e1 = mFrozen[k_e1];
    [[maybe_unused]] const double e2 = mFrozen[k_e2];
    [[maybe_unused]] const double efin = mFrozen[k_efin];
    [[maybe_unused]] const double awfin = mFrozen[k_awfin];
    [[maybe_unused]] const double awn1 = mFrozen[k_awn1];
    [[maybe_unused]] const double awn2 = mFrozen[k_awn2];
    [[maybe_unused]] const double awp1 = mFrozen[k_awp1];
    [[maybe_unused]] const double awp2 = mFrozen[k_awp2];
    [[maybe_unused]] const double gamma1 = mFrozen[k_gamma1];
    [[maybe_unused]] const double gamma2 = mFrozen[k_gamma2];
    [[maybe_unused]] const double hthrust0 = mFrozen[k_hthrust0];
    [[maybe_unused]] const double ia1 = mFrozen[k_ia1];
    [[maybe_unused]] const double ia2 = mFrozen[k_ia2];
    [[maybe_unused]] const double Ix0 = mFrozen[k_Ix0];
    [[maybe_unused]] const double Ixz0 = mFrozen[k_Ixz0];
    [[maybe_unused]] const double Iy0 = mFrozen[k_Iy0];
    [[maybe_unused]] const double Iz0 = mFrozen[k_Iz0];
    [[maybe_unused]] const double lambda1 = mFrozen[k_lambda1];
    [[maybe_unused]] const double lambda2 = mFrozen[k_lambda2];
    [[maybe_unused]] const double lambdafin = mFrozen[k_lambdafin];
    [[maybe_unused]] const double lc10 = mFrozen[k_lc10];
    [[maybe_unused]] const double lc20 = mFrozen[k_lc20];
    [[maybe_unused]] const double lc120 = mFrozen[k_lc120];
    [[maybe_unused]] const double lcfin0 = mFrozen[k_lcfin0];
    [[maybe_unused]] const double Med = mFrozen[k_Med];
    [[maybe_unused]] const double rc10 = mFrozen[k_rc10];
    [[maybe_unused]] const double rc20 = mFrozen[k_rc20];
    [[maybe_unused]] const double rcfin0 = mFrozen[k_rcfin0];
    [[maybe_unused]] const double S1 = mFrozen[k_S1];
    [[maybe_unused]] const double S20 = mFrozen[k_S20];
    [[maybe_unused]] const double Sbh0 = mFrozen[k_Sbh0];
    [[maybe_unused]] const double Sbv0 = mFrozen[k_Sbv0];
    [[maybe_unused]] const double Sfin0 = mFrozen[k_Sfin0];
    [[maybe_unused]] const double xbach0 = mFrozen[k_xbach0];
    [[maybe_unused]] const double xbacv0 = mFrozen[k_xbacv0];
    [[maybe_unused]] const double xbcge0 = mFrozen[k_xbcge0];
    [[maybe_unused]] const double xcargo0 = mFrozen[k_xcargo0];
    [[maybe_unused]] const double xfuel0 = mFrozen[k_xfuel0];
    [[maybe_unused]] const double xw10 = mFrozen[k_xw10];
    [[maybe_unused]] const double xw20 = mFrozen[k_xw20];
    [[maybe_unused]] const double xwfin0 = mFrozen[k_xwfin0];
    [[maybe_unused]] const double xeng0 = mFrozen[k_xeng0];
    [[maybe_unused]] const double yeng0 = mFrozen[k_yeng0];
    [[maybe_unused]] const double g0 = mFrozen[k_g0];
    [[maybe_unused]] const double kground = mFrozen[k_kground];
    [[maybe_unused]] const double cground = mFrozen[k_cground];
    mCore.velocitiesEarth(mVx, mVy, mVz);
    mCore.eulerAngles(mPhi, mThetao, mPsi);

    const double thal1 = *mpAngle[al1], thar1 = *mpAngle[ar1], thal12 = *mpAngle[al12], thar12 = *mpAngle[ar12];
    const double thal2 = *mpAngle[al2], thar2 = *mpAngle[ar2], thfin = *mpAngle[fin];
    const double qpress = mQpress, Alpha = mAlpha, Beta = mBeta, S2 = mS2, Sbh = mSbh, Sfin = mSfin;
    const double dt = mTimestep;

    mCport[al1] = CLde1 * mLc1 * qpress * S1 * (Alpha + thal1);
    mCport[ar1] = CLde1 * mLc1 * qpress * S1 * (Alpha + thar1);
    mCport[al12] = CLde12 * mLc12 * qpress * S1 * (Alpha + thal12);
    mCport[ar12] = CLde12 * mLc12 * qpress * S1 * (Alpha + thar12);
    mCport[al2] = CLde2 * mLc2 * qpress * S2 * (Alpha + thal2);
    mCport[ar2] = CLde2 * mLc2 * qpress * S2 * (Alpha + thar2);
    mCport[fin] = CLdefin * mLcfin * qpress * Sfin * (Beta + thfin);
    mZcport[al1] = CLde1 * mLc1 * dt * qpress * S1;
    mZcport[ar1] = mZcport[al1];
    mZcport[al12] = CLde12 * mLc12 * dt * qpress * S1;
    mZcport[ar12] = mZcport[al12];
    mZcport[al2] = CLde2 * mLc2 * dt * qpress * S2;
    mZcport[ar2] = mZcport[al2];
    mZcport[fin] = CLdefin * mLcfin * dt * qpress * Sfin;

    mCL1 = CLde1 * (thal1 + thar1) + CLde12 * (thal12 + thar12) + mCL1w
           + S2 * (CLde2 * (thal2 + thar2) + mCL2w) / S1 + CLalphabh * Sbh * std::sin(Alpha) / S1;
    mCd1 = Cd01 + Cd0b * Sbh / S1 + mKl + mKr + mCDi1
           + S2
                 * (Cd02 + CDragInd(Alpha * dah2 - ia2 + thal2, AR2, e2, CLalpha2, ap2, an2, awp2, awn2) / 2.0
                    + CDragInd(Alpha * dah2 - ia2 + thar2, AR2, e2, CLalpha2, ap2, an2, awp2, awn2) / 2.0)
                 / S1;
}

void AeroAircraft6DOFS::writeOutputs()
{
    const Aero6DofCore& s = mCore;
    for (int i = 0; i < kNumPorts; ++i) {
        *mpC[i] = mCport[i];
        *mpZc[i] = mZcport[i];
    }
    *mpXcg = s.xcg;
    *mpYcg = s.ycg;
    *mpZcg = s.zcg;
    *mpVx = mVx;
    *mpVy = mVy;
    *mpVz = mVz;
    *mpPsi = mPsi;
    *mpThetao = mThetao;
    *mpPhi = mPhi;
    *mpUb = s.Ub;
    *mpVb = s.Vb;
    *mpWb = s.Wb;
    *mpPb = s.Pb;
    *mpQb = s.Qb;
    *mpRb = s.Rb;
    *mpQ0 = s.q0;
    *mpQ1 = s.q1;
    *mpQ2 = s.q2;
    *mpQ3 = s.q3;
    *mpAlphaAttack = mAlpha;
    *mpBetaSlip = mBeta;
    *mpAltitude = -s.zcg;
    *mpGfx = s.Fx / s.m;
    *mpGfy = s.Fy / s.m;
    *mpGfz = s.Fz / s.m;
    *mpCL1 = mCL1;
    *mpCd1 = mCd1;
    *mpFax = -mDsum;
    *mpFaz = -mLsum;
}

void AeroAircraft6DOFS::initialize()
{
    for (int i = 0; i < kNumPorts; ++i) {
        mpAngle[i] = getSafeNodeDataPtr(mpPorts[i], NodeMechanicRotational::Angle);
        mpC[i] = getSafeNodeDataPtr(mpPorts[i], NodeMechanicRotational::WaveVariable);
        mpZc[i] = getSafeNodeDataPtr(mpPorts[i], NodeMechanicRotational::CharImpedance);
        mCport[i] = *mpC[i];
        mZcport[i] = *mpZc[i];
    }
    // Hopsan quirk: these inputs are sampled only here.
    for (int i = 0; i < kNumFrozen; ++i) { mFrozen[i] = *mpFrozen[i]; }

    Aero6DofCore& s = mCore;
    s.Ub = *mpUb;
    s.Vb = *mpVb;
    s.Wb = *mpWb;
    s.Pb = *mpPb;
    s.Qb = *mpQb;
    s.Rb = *mpRb;
    s.xcg = *mpXcg;
    s.ycg = *mpYcg;
    s.zcg = *mpZcg;
    mPhi = *mpPhi;
    mThetao = *mpThetao;
    mPsi = *mpPsi;
    mVx = *mpVx;
    mVy = *mpVy;
    mVz = *mpVz;
    mCL1 = *mpCL1;
    mCd1 = *mpCd1;
    // The quaternion start values are ignored: it is built from the Euler start values.
    s.setQuaternionFromEuler(mPhi, mThetao, mPsi);
    explicitQuantities();
    s.computeDelayedParts(mTimestep);
    // No initial step for this type.
}

void AeroAircraft6DOFS::simulateOneTimestep()
{
    explicitQuantities();
    for (int iter = 1; iter <= 2; ++iter) {
        if (!mCore.iterate(iter, mTimestep)) { stopSimulation("AeroAircraft6DOFS: singular Jacobian"); }
        evalOutputs();
    }
    mCore.computeDelayedParts(mTimestep);
    writeOutputs();
}

TLMHUB_REGISTER_COMPONENT(AeroAircraft6DOFS, "Aero")

} // namespace tlmhub
