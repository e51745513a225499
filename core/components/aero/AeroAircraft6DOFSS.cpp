#include "core/components/aero/AeroAircraft6DOFSS.h"

#include "core/ComponentFactory.h"
#include "core/components/aero/AircraftControlSurfaces.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

#include <cmath>

namespace tlmhub {

namespace {
using enum aircraft::ControlSurface;

struct VarInfo {
    const char* name;
    const char* desc;
    const char* unit;
    double defaultValue;
};
// Order matches AeroAircraft6DOFSS::Input.
const VarInfo kInputs[AeroAircraft6DOFSS::kNumInputs] = {
    {"deCD", "Drag coefficient increment", "", 0.0},
    {"deCY", "Side force coefficient increment", "", 0.0},
    {"deCL", "Lift coefficient increment", "", 0.0},
    {"deCl", "Roll moment coefficient increment", "", 0.0},
    {"deCm", "Pitch moment coefficient increment", "", 0.0},
    {"deCn", "Yaw moment coefficient increment", "", 0.0},
    {"thrustl", "Thrust left engine", "N", 0.0},
    {"thrustr", "Thrust right engine", "N", 0.0},
    {"dezthrustl", "Thrust angle z left", "rad", 0.0},
    {"dezthrustr", "Thrust angle z right", "rad", 0.0},
    {"deythrustl", "Thrust angle y left", "rad", 0.0},
    {"deythrustr", "Thrust angle y right", "rad", 0.0},
    {"Mfuel", "Fuel mass", "kg", 0.0},
    {"Mcargo", "Cargo mass", "kg", 0.0},
    {"rho", "Air density", "kg/m3", 1.25},
    {"vM", "Speed of sound", "m/s", 340.0},
    {"vturbx", "Wind velocity x (earth)", "m/s", 0.0},
    {"vturby", "Wind velocity y (earth)", "m/s", 0.0},
    {"vturbz", "Wind velocity z (earth)", "m/s", 0.0},
    {"wturbx", "Turbulence rotation x", "rad/s", 0.0},
    {"wturby", "Turbulence rotation y", "rad/s", 0.0},
    {"wturbz", "Turbulence rotation z", "rad/s", 0.0},
    {"afin", "Stall angle fin", "rad", 0.3},
    {"an1", "Negative stall angle wing 1", "rad", 0.6},
    {"an2", "Negative stall angle wing 2", "rad", 0.6},
    {"ap1", "Positive stall angle wing 1", "rad", 0.9},
    {"ap2", "Positive stall angle wing 2", "rad", 0.7},
    {"AR1", "Aspect ratio wing 1", "", 3.62},
    {"AR2", "Aspect ratio wing 2", "", 3.62},
    {"ARfin", "Aspect ratio fin", "", 1.5},
    {"Cd01", "Zero-lift drag wing 1", "", 0.0045},
    {"Cd02", "Zero-lift drag wing 2", "", 0.0045},
    {"Cd0b", "Body drag coefficient", "", 0.03},
    {"Cd0fin", "Fin drag coefficient", "", 0.0045},
    {"CdW0", "Wave drag coefficient", "", 0.048},
    {"CLalpha1", "Lift slope wing 1", "", 2.1},
    {"CLalpha2", "Lift slope wing 2", "", 2.2},
    {"CLalphabh", "Body lift slope horizontal", "", 2.0},
    {"CLalphabv", "Body lift slope vertical", "", 2.0},
    {"CLalphafin", "Lift slope fin", "", 0.8},
    {"CLde1", "Lift per aileron deflection", "", 0.1},
    {"CLde12", "Lift per flap deflection", "", 0.2},
    {"Cdide1", "Induced drag per aileron deflection", "", 0.0},
    {"Cdide12", "Induced drag per flap deflection", "", 0.0},
    {"Cdide112", "Induced drag aileron-flap coupling", "", 0.0},
    {"de10", "Aileron deflection offset", "rad", 0.01},
    {"de120", "Flap deflection offset", "rad", 0.01},
    {"dM", "Transonic transition width", "", 0.1},
    {"Cm01", "Zero-lift moment coefficient", "", -0.1},
    {"Cmfs1", "Moment coefficient stall", "", -0.5},
    {"Cmde1", "Moment per aileron deflection", "", 0.02},
    {"Cmde12", "Moment per flap deflection", "", 0.1},
    {"CLdefin", "Lift per rudder deflection", "", 0.0827084},
    {"Cydeelev", "Side force per differential elevator", "", 0.1},
    {"Cnbeta", "Yaw moment per side slip", "", 0.0},
    {"dah1", "Downwash factor wing 1", "", 1.0},
    {"dah2", "Downwash factor wing 2", "", 1.0},
    {"en", "Base of the transition exponential", "", 2.71828},
    {"e1", "Oswald factor wing 1", "", 0.95},
    {"e2", "Oswald factor wing 2", "", 0.95},
    {"efin", "Oswald factor fin", "", 0.95},
    {"epsM", "Mach smoothing factor", "", 0.1},
    {"awfin", "CL exponent fin", "", 0.2},
    {"awn1", "CL exponent negative wing 1", "", 0.2},
    {"awn2", "CL exponent negative wing 2", "", 0.2},
    {"awp1", "CL exponent positive wing 1", "", 0.2},
    {"awp2", "CL exponent positive wing 2", "", 0.2},
    {"gamma1", "Dihedral wing 1", "rad", -0.0872665},
    {"gamma2", "Dihedral wing 2", "rad", -0.0872665},
    {"hthrust0", "Normalised engine vertical position", "", 0.0},
    {"ia1", "Incidence angle wing 1", "rad", 0.0},
    {"ia2", "Incidence angle wing 2", "rad", 0.02},
    {"Ix0", "Normalised inertia Ix", "", 0.0147},
    {"Ixz0", "Normalised inertia Ixz", "", 0.0055},
    {"Iy0", "Normalised inertia Iy", "", 1.131},
    {"Iz0", "Normalised inertia Iz", "", 1.279},
    {"lambda1", "Sweep wing 1", "rad", 0.436332},
    {"lambda2", "Sweep wing 2", "rad", 0.436332},
    {"lambdafin", "Sweep fin", "rad", 0.785398},
    {"lc10", "Normalised aileron hinge arm", "", 0.01},
    {"lc20", "Normalised elevator hinge arm", "", 0.05},
    {"lc120", "Normalised flap hinge arm", "", 0.01},
    {"lcfin0", "Normalised rudder hinge arm", "", 0.01},
    {"Me", "Empty mass", "kg", 8700.0},
    {"mac0", "Normalised mean aerodynamic chord", "", 1.0},
    {"rc10", "Normalised aileron moment arm", "", 0.25},
    {"rc120", "Normalised flap moment arm", "", 0.25},
    {"rc20", "Normalised elevator moment arm", "", 0.15},
    {"rcfin0", "Normalised rudder moment arm", "", 0.1},
    {"S1", "Wing area 1", "m2", 27.0},
    {"S20", "Normalised wing area 2", "", 0.36},
    {"Sbh0", "Normalised body horizontal area", "", 0.2},
    {"Sbv0", "Normalised body vertical area", "", 0.1},
    {"Sfin0", "Normalised fin area", "", 0.17},
    {"xbach0", "Normalised body ac horizontal", "", 3.0},
    {"xbacv0", "Normalised body ac vertical", "", 3.0},
    {"xbcge0", "Normalised body cg", "", 3.0},
    {"xcargo0", "Normalised cargo position", "", 3.0},
    {"xfuel0", "Normalised fuel position", "", 3.0},
    {"xw10", "Normalised wing 1 position", "", 3.0},
    {"xw20", "Normalised wing 2 position", "", 4.8},
    {"xwfin0", "Normalised fin position", "", 4.8},
    {"xeng0", "Normalised engine position", "", 4.8},
    {"yeng0", "Normalised engine lateral offset", "", 0.0},
    {"g0", "Gravity acceleration", "m/s2", 9.81},
    {"kground", "Ground stiffness", "N/m", 10000.0},
    {"cground", "Ground damping", "Ns/m", 1000.0},
};
// Order matches AeroAircraft6DOFSS::Output.
const VarInfo kOutputs[AeroAircraft6DOFSS::kNumOutputs] = {
    {"xcg", "Position x (earth)", "m", 0.0},
    {"ycg", "Position y (earth)", "m", 0.0},
    {"zcg", "Position z (earth, down)", "m", 0.0},
    {"vx", "Velocity x (earth)", "m/s", 0.0},
    {"vy", "Velocity y (earth)", "m/s", 0.0},
    {"vz", "Velocity z (earth)", "m/s", 0.0},
    {"Psi", "Heading", "rad", 0.0},
    {"Thetao", "Pitch", "rad", 0.0},
    {"Phi", "Roll", "rad", 0.0},
    {"Ub", "Body velocity x", "m/s", 100.0},
    {"Vb", "Body velocity y", "m/s", 0.0},
    {"Wb", "Body velocity z", "m/s", 0.0},
    {"v", "Air speed", "m/s", 0.0},
    {"Pb", "Body roll rate", "rad/s", 0.0},
    {"Qb", "Body pitch rate", "rad/s", 0.0},
    {"Rb", "Body yaw rate", "rad/s", 0.0},
    {"q0", "Quaternion 0", "", 0.0},
    {"q1", "Quaternion 1", "", 0.0},
    {"q2", "Quaternion 2", "", 0.0},
    {"q3", "Quaternion 3", "", 0.0},
    {"AlphaAttack", "Angle of attack", "rad", 0.0},
    {"BetaSlip", "Side slip angle", "rad", 0.0},
    {"altitude", "Altitude", "m", 0.0},
    {"gfx", "Acceleration x (body)", "m/s2", 0.0},
    {"gfy", "Acceleration y (body)", "m/s2", 0.0},
    {"gfz", "Acceleration z (body)", "m/s2", 0.0},
    {"CL1", "Lift coefficient wing 1", "", 0.0},
    {"Cd1", "Drag coefficient wing 1", "", 0.0},
    {"CL2", "Lift coefficient wing 2", "", 0.0},
    {"Cd2", "Drag coefficient wing 2", "", 0.0},
    {"CLtot", "Total lift coefficient", "", 0.0},
    {"Cdtot", "Total drag coefficient", "", 0.0},
    {"Lift1", "Lift wing 1", "N", 0.0},
    {"Lift2", "Lift wing 2", "N", 0.0},
    {"Fax", "Aerodynamic force x", "N", 0.0},
    {"Faz", "Aerodynamic force z", "N", 0.0},
};
} // namespace

void AeroAircraft6DOFSS::configure()
{
    for (int i = 0; i < kNumPorts; ++i) { mpPorts[i] = addPowerPort(aircraft::kControlSurfacePortNames[i], NodeType::MechanicRotational); }
    for (int i = 0; i < kNumInputs; ++i) {
        addInputVariable(kInputs[i].name, kInputs[i].desc, kInputs[i].unit, kInputs[i].defaultValue, &mpIn[i]);
    }
    for (int i = 0; i < kNumOutputs; ++i) {
        addOutputVariable(kOutputs[i].name, kOutputs[i].desc, kOutputs[i].unit, kOutputs[i].defaultValue, &mpOut[i]);
    }
}

void AeroAircraft6DOFSS::explicitQuantities()
{
    const auto in = [this](int k) { return *mpIn[k]; };
    const double deCD = in(k_deCD), deCY = in(k_deCY), deCL = in(k_deCL), deCl = in(k_deCl), deCm = in(k_deCm),
                 deCn = in(k_deCn);
    const double thrustl = in(k_thrustl), thrustr = in(k_thrustr);
    const double dezthrustl = in(k_dezthrustl), dezthrustr = in(k_dezthrustr);
    const double deythrustl = in(k_deythrustl), deythrustr = in(k_deythrustr);
    const double Mfuel = in(k_Mfuel), Mcargo = in(k_Mcargo), rho = in(k_rho), vM = in(k_vM);
    const double vturbx = in(k_vturbx), vturby = in(k_vturby), vturbz = in(k_vturbz);
    const double wturbx = in(k_wturbx), wturby = in(k_wturby), wturbz = in(k_wturbz);
    const double afin = in(k_afin), an1 = in(k_an1), an2 = in(k_an2), ap1 = in(k_ap1), ap2 = in(k_ap2);
    const double AR1 = in(k_AR1), AR2 = in(k_AR2);
    const double Cd01 = in(k_Cd01), Cd02 = in(k_Cd02), Cd0b = in(k_Cd0b), Cd0fin = in(k_Cd0fin), CdW0 = in(k_CdW0);
    const double CLalpha1 = in(k_CLalpha1), CLalpha2 = in(k_CLalpha2), CLalphabh = in(k_CLalphabh),
                 CLalphabv = in(k_CLalphabv), CLalphafin = in(k_CLalphafin);
    const double CLde1 = in(k_CLde1), CLde12 = in(k_CLde12);
    const double Cdide1 = in(k_Cdide1), Cdide12 = in(k_Cdide12), Cdide112 = in(k_Cdide112);
    const double de10 = in(k_de10), de120 = in(k_de120), dM = in(k_dM);
    const double Cm01 = in(k_Cm01), Cmfs1 = in(k_Cmfs1), Cmde1 = in(k_Cmde1), Cmde12 = in(k_Cmde12);
    const double CLdefin = in(k_CLdefin), Cydeelev = in(k_Cydeelev), Cnbeta = in(k_Cnbeta);
    const double dah1 = in(k_dah1), dah2 = in(k_dah2), en = in(k_en), e1 = in(k_e1), e2 = in(k_e2),
                 epsM = in(k_epsM);
    const double awfin = in(k_awfin), awn1 = in(k_awn1), awn2 = in(k_awn2), awp1 = in(k_awp1), awp2 = in(k_awp2);
    const double ia1 = in(k_ia1), ia2 = in(k_ia2);
    const double Ix0 = in(k_Ix0), Ixz0 = in(k_Ixz0), Iy0 = in(k_Iy0), Iz0 = in(k_Iz0);
    const double lambda1 = in(k_lambda1), lambda2 = in(k_lambda2);
    const double lc10 = in(k_lc10), lc20 = in(k_lc20), lc120 = in(k_lc120), lcfin0 = in(k_lcfin0);
    const double Me = in(k_Me), mac0 = in(k_mac0), rc10 = in(k_rc10), rc20 = in(k_rc20);
    const double S1 = in(k_S1), S20 = in(k_S20), Sbh0 = in(k_Sbh0), Sbv0 = in(k_Sbv0), Sfin0 = in(k_Sfin0);
    const double xbcge0 = in(k_xbcge0), xcargo0 = in(k_xcargo0), xfuel0 = in(k_xfuel0), xw10 = in(k_xw10),
                 xw20 = in(k_xw20), xwfin0 = in(k_xwfin0), xeng0 = in(k_xeng0), yeng0 = in(k_yeng0);
    const double g0 = in(k_g0), kground = in(k_kground);

    Aero6DofCore& st = mCore;
    const double thal1 = *mpAngle[al1], thar1 = *mpAngle[ar1], thal12 = *mpAngle[al12], thar12 = *mpAngle[ar12];
    const double thal2 = *mpAngle[al2], thar2 = *mpAngle[ar2], thfin = *mpAngle[fin];

    // Geometry. b2 uses S2 from the previous evaluation (quirk, see the header).
    const double b1 = std::sqrt(AR1 * S1);
    const double b2 = std::sqrt(AR2 * mS2);
    const double smc = std::sqrt(S1 / AR1);
    const double mac = mac0 * smc;
    st.Ix = AR1 * Ix0 * Me * S1;
    st.Ixz = Ixz0 * Me * S1;
    st.Iy = (Iy0 * Me * S1) / AR1;
    st.Iz = (Iz0 * Me * S1) / AR1;
    mLc1 = lc10 * mac;
    mLc2 = lc20 * mac;
    mLc12 = lc120 * mac;
    mLcfin = lcfin0 * mac;
    const double rc1 = b1 * rc10;
    const double rc2 = b1 * rc20;
    const double S2 = S1 * S20;
    const double Sbh = S1 * Sbh0;
    const double Sbv = S1 * Sbv0;
    const double Sfin = S1 * Sfin0;
    mS2 = S2;
    mSbh = Sbh;
    mSfin = Sfin;
    const double xbcge = mac * xbcge0;
    const double xcargo = mac * xcargo0;
    const double xfuel = mac * xfuel0;
    const double xw1 = mac * xw10;
    const double xw2 = mac * xw20;
    const double xwfin = mac * xwfin0;
    const double xeng = mac * xeng0;
    const double yeng = b1 * yeng0;

    // Mach corrections with the previous v (quirk: v is only updated further down).
    const double vOld = mV;
    const double mr2 = (vOld * vOld) / (vM * vM);
    const double W = (1.0 - mr2) * (1.0 - mr2) + (epsM * epsM) * (vOld * vOld) / (vM * vM);
    const double betaM = std::pow(W, 0.25);
    const double CLalpha1e = CLalpha1 / betaM;
    const double CLalpha2e = CLalpha2 / betaM;
    const double Told = 1.0 + std::pow(en, (-2.0 * (vOld - (1.0 - dM) * vM)) / (dM * vM));
    const double e1e =
        e1 - (e1 * (1.0 - (0.31831 * (-2.0 + 4.0 * AR1 * std::pow(W, 0.25)) * SecL(lambda1)) / ((AR1 * AR1) * std::sqrt(W))))
                 / Told;
    const double e2e =
        e2 - (e2 * (1.0 - (0.31831 * (-2.0 + 4.0 * AR2 * std::pow(W, 0.25)) * SecL(lambda2)) / ((AR2 * AR2) * std::sqrt(W))))
                 / Told;
    mCLalpha2e = CLalpha2e;
    mE2e = e2e;

    // Wind in body axes; quirk: the y-velocity also gets the earth-x row wx.
    double r11, r12, r13, r21, r22, r23, r31, r32, r33;
    st.dcm(r11, r12, r13, r21, r22, r23, r31, r32, r33);
    const double Uw = st.Ub + r11 * vturbx + r12 * vturby + r13 * vturbz;
    const double Vw = st.Vb + r11 * vturbx + r12 * vturby + r13 * vturbz;
    const double Ww = r31 * vturbx + r32 * vturby + r33 * vturbz + st.Wb;
    const double v = std::sqrt(0.0001 + Uw * Uw + Vw * Vw + Ww * Ww);
    mV = v;
    const double Alpha = Atan2L(Ww, 0.0001 + st.Ub + r11 * vturbx + r12 * vturby + r13 * vturbz);
    const double qpress = (rho * (v * v)) / 2.0;
    const double Beta = Atan2L(Vw, std::sqrt(0.0001 + Uw * Uw + Ww * Ww));
    mAlpha = Alpha;
    mBeta = Beta;
    mQpress = qpress;
    const double mass = Mcargo + Me + Mfuel;
    const double xbcg = (Me * xbcge + Mcargo * xcargo + Mfuel * xfuel) / mass;
    const double Tn = 1.0 + std::pow(en, (-2.0 * (v - (1.0 - dM) * vM)) / (dM * vM));
    mTn = Tn;
    const double cosA = std::cos(Alpha), sinA = std::sin(Alpha), cosB = std::cos(Beta), sinB = std::sin(Beta);

    const double a1 = Alpha * dah1 - ia1;
    const double a2l = Alpha * dah2 - ia2 + thal2;
    const double a2r = Alpha * dah2 - ia2 + thar2;
    mA1 = a1;
    mA2l = a2l;
    mA2r = a2r;
    mKl = Cdide1 * ((-de10 + thal1) * (-de10 + thal1)) - Cdide112 * (-de10 + thal1) * (-de120 + thal12)
          + Cdide12 * ((-de120 + thal12) * (-de120 + thal12));
    mKr = Cdide1 * ((-de10 + thar1) * (-de10 + thar1)) - Cdide112 * (-de10 + thar1) * (-de120 + thar12)
          + Cdide12 * ((-de120 + thar12) * (-de120 + thar12));
    mCDi1 = CDragInd(a1, AR1, e1e, CLalpha1e, ap1, an1, awp1, awn1);
    mCL1w = CLift(a1, CLalpha1e, ap1, an1, awp1, awn1);
    const double Dragl1 = qpress * S1 * (Cd01 / 2.0 + mKl + mCDi1 / 2.0);
    const double Dragr1 = qpress * S1 * (Cd01 / 2.0 + mKr + mCDi1 / 2.0);
    const double Liftl1 = qpress * S1 * (CLde1 * thal1 + CLde12 * thal12 + mCL1w / 2.0);
    const double Liftr1 = qpress * S1 * (CLde1 * thar1 + CLde12 * thar12 + mCL1w / 2.0);
    mLift1 = Liftl1 + Liftr1;
    const double Dragl2 = qpress * S2 * (Cd02 / 2.0 + CDragInd(a2l, AR2, e2e, CLalpha2e, ap2, an2, awp2, awn2) / 2.0);
    const double Dragr2 = qpress * S2 * (Cd02 / 2.0 + CDragInd(a2r, AR2, e2e, CLalpha2e, ap2, an2, awp2, awn2) / 2.0);
    const double Liftl2 = (qpress * S2 * CLift(a2l, CLalpha2e, ap2, an2, awp2, awn2)) / 2.0;
    const double Liftr2 = (qpress * S2 * CLift(a2r, CLalpha2e, ap2, an2, awp2, awn2)) / 2.0;
    mLift2 = Liftl2 + Liftr2;
    const double Liftb = CLalphabh * qpress * Sbh * sinA;
    const double Dragb = qpress * ((CdW0 * S1) / Tn + Cd0b * Sbh);
    const double Cfin =
        qpress * Sfin * CLift(-Beta - (CLdefin * thfin) / CLalphafin, CLalphafin, afin, afin, awfin, awfin);
    const double Dragfin = Cd0fin * qpress * Sfin;
    // (Mdvtheta/Mdvpsi of the generated original are computed but unused: omitted.)
    const double Dsum = Dragb + Dragfin + Dragl1 + Dragl2 + Dragr1 + Dragr2 + deCD * qpress * S1;
    const double Lsum = Liftb + Liftl1 + Liftl2 + Liftr1 + Liftr2 + 2.0 * deCL * qpress * S1;
    const double Y = -Cfin - 2.0 * deCY * qpress * S1 - Cydeelev * qpress * S2 * (thal2 - thar2)
                     + CLalphabv * qpress * Sbv * sinB;
    mDsum = Dsum;
    mLsum = Lsum;
    const double H = onPositive(st.zcg);

    // Thrust terms as in Hopsan: Fx, Fy, Fz use dezthrustr for both engines.
    st.Fx = -Dsum * cosA * cosB + thrustl * std::cos(deythrustl) * std::cos(dezthrustr)
            + thrustr * std::cos(deythrustr) * std::cos(dezthrustr) + Lsum * sinA - cosA * sinB * Y;
    st.Fy = -Dsum * sinB + cosB * Y - thrustl * std::cos(dezthrustr) * std::sin(deythrustl)
            - thrustr * std::cos(dezthrustr) * std::sin(deythrustr);
    st.Fz = -Lsum * cosA - kground * st.zcg * H - Dsum * cosB * sinA - sinA * sinB * Y
            - thrustl * std::cos(deythrustl) * std::sin(dezthrustr) - thrustr * std::cos(deythrustr) * std::sin(dezthrustr);
    st.Lb = (Liftl1 - Liftr1) * rc1 + (Liftl2 - Liftr2) * rc2 + 2.0 * deCl * qpress * S1
            - (0.12249999999999998 * qpress * ((b1 * b1) * CLalpha1e * S1 + (b2 * b2) * CLalpha2e * S2)
               * (st.Pb + r11 * wturbx + r12 * wturby + r13 * wturbz))
                  / (0.1 + v)
            + yeng * (thrustl * std::cos(deythrustl) * std::sin(dezthrustl)
                      - thrustr * std::cos(deythrustr) * std::sin(dezthrustr));
    st.Mb = deCm * qpress * S1
            + qpress * S1
                  * (-(Cmde1 * thal1) - Cmde12 * thal12 - Cmde1 * thar1 - Cmde12 * thar12
                     - (smc * (CLde1 * thal1 + CLde12 * thal12 + mCL1w / 2.0)) / (4.0 * Tn)
                     - (smc * (CLde1 * thar1 + CLde12 * thar12 + mCL1w / 2.0)) / (4.0 * Tn)
                     + CMoment(a1, Cm01, Cmfs1, ap1, an1, awp1, awn1))
            + (xbcg - xw1) * ((Liftl1 + Liftr1) * cosA + (Dragl1 + Dragr1) * sinA)
            + (xbcg - xw2) * ((Liftl2 + Liftr2) * cosA - (Dragl2 + Dragr2) * sinA)
            + (xbcg - xeng) * (thrustl * std::cos(deythrustl) * std::sin(dezthrustl)
                               + thrustr * std::cos(deythrustr) * std::sin(dezthrustr));
    // Quirk: Cnbeta only acts multiplied by deCn.
    st.Nb = (-Dragl1 + Dragr1) * rc1 + (-Dragl2 + Dragr2) * rc2 + Beta * Cnbeta * deCn * qpress * S1
            - Cfin * (-xbcg + xwfin)
            + (xbcg - xeng) * (thrustl * std::cos(dezthrustl) * std::sin(deythrustl)
                               + thrustr * std::cos(dezthrustr) * std::sin(deythrustr));
    st.m = mass;
    st.g = g0;
    st.k = kground;
    (void)wturby;
    (void)wturbz;
}

void AeroAircraft6DOFSS::evalOutputs()
{
    const auto in = [this](int k) { return *mpIn[k]; };
    const double S1 = in(k_S1), CLde1 = in(k_CLde1), CLde12 = in(k_CLde12), CLdefin = in(k_CLdefin);
    const double CLalphabh = in(k_CLalphabh), Cd01 = in(k_Cd01), Cd02 = in(k_Cd02), CdW0 = in(k_CdW0),
                 Cd0b = in(k_Cd0b), Cd0fin = in(k_Cd0fin);
    const double AR2 = in(k_AR2), ap2 = in(k_ap2), an2 = in(k_an2), awp2 = in(k_awp2), awn2 = in(k_awn2);
    Aero6DofCore& st = mCore;
    double* o = mOut;

    st.velocitiesEarth(o[o_vx], o[o_vy], o[o_vz]);
    st.eulerAngles(o[o_Phi], o[o_Thetao], o[o_Psi]);

    const double thal1 = *mpAngle[al1], thar1 = *mpAngle[ar1], thal12 = *mpAngle[al12], thar12 = *mpAngle[ar12];
    const double thfin = *mpAngle[fin];
    const double qpress = mQpress, Beta = mBeta, S2 = mS2, Sbh = mSbh, Sfin = mSfin;
    const double a1 = mA1, a2l = mA2l, a2r = mA2r, CLalpha2e = mCLalpha2e;
    const double dt = mTimestep;

    mCport[al1] = CLde1 * mLc1 * qpress * S1 * (a1 + thal1);
    mCport[ar1] = CLde1 * mLc1 * qpress * S1 * (a1 + thar1);
    mCport[al12] = CLde12 * mLc12 * qpress * S1 * (a1 + thal12);
    mCport[ar12] = CLde12 * mLc12 * qpress * S1 * (a1 + thar12);
    mCport[al2] = CLalpha2e * mLc2 * qpress * S2 * a2l;
    mCport[ar2] = CLalpha2e * mLc2 * qpress * S2 * a2r;
    mCport[fin] = CLdefin * mLcfin * qpress * Sfin * (Beta + thfin);
    mZcport[al1] = CLde1 * mLc1 * dt * qpress * S1;
    mZcport[ar1] = mZcport[al1];
    mZcport[al12] = CLde12 * mLc12 * dt * qpress * S1;
    mZcport[ar12] = mZcport[al12];
    mZcport[al2] = CLalpha2e * mLc2 * dt * qpress * S2;
    mZcport[ar2] = mZcport[al2];
    mZcport[fin] = CLdefin * mLcfin * dt * qpress * Sfin;

    o[o_AlphaAttack] = mAlpha;
    o[o_BetaSlip] = mBeta;
    o[o_altitude] = -st.zcg;
    o[o_gfx] = st.Fx / st.m;
    o[o_gfy] = st.Fy / st.m;
    o[o_gfz] = st.Fz / st.m;
    o[o_Faz] = -mLsum;
    o[o_Fax] = -mDsum;
    o[o_CL1] = CLde1 * (thal1 + thar1) + CLde12 * (thal12 + thar12) + mCL1w;
    o[o_CL2] = (CLift(a2l, CLalpha2e, ap2, an2, awp2, awn2) + CLift(a2r, CLalpha2e, ap2, an2, awp2, awn2)) / 2.0;
    o[o_CLtot] = o[o_CL1] + S2 * o[o_CL2] / S1 + CLalphabh * Sbh * std::sin(mAlpha) / S1;
    o[o_Cd1] = Cd01 + mKl + mKr + mCDi1;
    o[o_Cd2] = Cd02
               + (CDragInd(a2l, AR2, mE2e, CLalpha2e, ap2, an2, awp2, awn2)
                  + CDragInd(a2r, AR2, mE2e, CLalpha2e, ap2, an2, awp2, awn2))
                     / 2.0;
    o[o_Cdtot] = Cd01 + CdW0 / mTn + Cd0b * Sbh / S1 + Cd0fin * Sfin / S1 + mKl + mKr + mCDi1 + S2 * o[o_Cd2] / S1;
    o[o_v] = mV;
    o[o_Lift1] = mLift1;
    o[o_Lift2] = mLift2;
}

void AeroAircraft6DOFSS::writeOutputs()
{
    const Aero6DofCore& s = mCore;
    for (int i = 0; i < kNumPorts; ++i) {
        *mpC[i] = mCport[i];
        *mpZc[i] = mZcport[i];
    }
    mOut[o_xcg] = s.xcg;
    mOut[o_ycg] = s.ycg;
    mOut[o_zcg] = s.zcg;
    mOut[o_Ub] = s.Ub;
    mOut[o_Vb] = s.Vb;
    mOut[o_Wb] = s.Wb;
    mOut[o_Pb] = s.Pb;
    mOut[o_Qb] = s.Qb;
    mOut[o_Rb] = s.Rb;
    mOut[o_q0] = s.q0;
    mOut[o_q1] = s.q1;
    mOut[o_q2] = s.q2;
    mOut[o_q3] = s.q3;
    for (int i = 0; i < kNumOutputs; ++i) { *mpOut[i] = mOut[i]; }
}

void AeroAircraft6DOFSS::initialize()
{
    for (int i = 0; i < kNumPorts; ++i) {
        mpAngle[i] = getSafeNodeDataPtr(mpPorts[i], NodeMechanicRotational::Angle);
        mpC[i] = getSafeNodeDataPtr(mpPorts[i], NodeMechanicRotational::WaveVariable);
        mpZc[i] = getSafeNodeDataPtr(mpPorts[i], NodeMechanicRotational::CharImpedance);
        mCport[i] = *mpC[i];
        mZcport[i] = *mpZc[i];
    }
    for (int i = 0; i < kNumOutputs; ++i) { mOut[i] = *mpOut[i]; }

    Aero6DofCore& s = mCore;
    s.Ub = mOut[o_Ub];
    s.Vb = mOut[o_Vb];
    s.Wb = mOut[o_Wb];
    s.Pb = mOut[o_Pb];
    s.Qb = mOut[o_Qb];
    s.Rb = mOut[o_Rb];
    s.xcg = mOut[o_xcg];
    s.ycg = mOut[o_ycg];
    s.zcg = mOut[o_zcg];
    // The Mach terms of the first evaluation use the start value of v; S2 starts at 0.
    mV = mOut[o_v];
    mS2 = 0.0;
    // The quaternion start values are ignored: it is built from the Euler start values.
    s.setQuaternionFromEuler(mOut[o_Phi], mOut[o_Thetao], mOut[o_Psi]);
    explicitQuantities();
    s.computeDelayedParts(mTimestep);
    // Hopsan quirk: initialisation ends with one full time step.
    simulateOneTimestep();
}

void AeroAircraft6DOFSS::simulateOneTimestep()
{
    explicitQuantities();
    for (int iter = 1; iter <= 2; ++iter) {
        if (!mCore.iterate(iter, mTimestep)) {
            stopSimulation("AeroAircraft6DOFSS: singular Jacobian");
            return;
        }
        evalOutputs();
    }
    mCore.computeDelayedParts(mTimestep);
    writeOutputs();
}

TLMHUB_REGISTER_COMPONENT(AeroAircraft6DOFSS, "Aero")

} // namespace tlmhub
