#include "core/components/hydraulic/HydraulicValve416.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicValve416::configure()
{
    mpPp = addPowerPort("Pp", NodeType::Hydraulic);
    mpPt = addPowerPort("Pt", NodeType::Hydraulic);
    mpPa = addPowerPort("Pa", NodeType::Hydraulic);
    mpPb = addPowerPort("Pb", NodeType::Hydraulic);

    addInputVariable("xvpa", "Opening of edge P-A", "m", 0.0, &mp_xvpa);
    addInputVariable("xvta", "Opening of edge A-T", "m", 0.0, &mp_xvta);
    addInputVariable("xvpb", "Opening of edge P-B", "m", 0.0, &mp_xvpb);
    addInputVariable("xvtb", "Opening of edge B-T", "m", 0.0, &mp_xvtb);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mp_rho);
    addInputVariable("Cq", "Flow coefficient", "-", 0.67, &mp_Cq);
    addInputVariable("Sd", "Spool diameter", "m", 0.001, &mp_Sd);
    addInputVariable("Frpa", "Circumference fraction P-A", "-", 1.0, &mp_Frpa);
    addInputVariable("Frta", "Circumference fraction A-T", "-", 1.0, &mp_Frta);
    addInputVariable("Frpb", "Circumference fraction P-B", "-", 1.0, &mp_Frpb);
    addInputVariable("Frtb", "Circumference fraction B-T", "-", 1.0, &mp_Frtb);
    addInputVariable("Xpa0", "Underlap P-A", "m", 0.0, &mp_Xpa0);
    addInputVariable("Xta0", "Underlap A-T", "m", 0.0, &mp_Xta0);
    addInputVariable("Xpb0", "Underlap P-B", "m", 0.0, &mp_Xpb0);
    addInputVariable("Xtb0", "Underlap B-T", "m", 0.0, &mp_Xtb0);
    addInputVariable("Xvmax", "Maximum opening", "m", 0.01, &mp_Xvmax);
    addInputVariable("plam", "Turbulence onset pressure", "Pa", 1.0e4, &mp_plam);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rho", "Cq", "Sd", "Frpa", "Frta", "Frpb", "Frtb", "Xpa0", "Xta0", "Xpb0", "Xtb0",
                      "Xvmax", "plam"}, false);
}

void HydraulicValve416::localExpressions()
{
    Ks = 1.4142135623730951 * Cq / std::sqrt(rho);
    Kspa = 3.14159 * Frpa * Ks * Sd * limit(Xpa0 + xvpa, 0.0, Xpa0 + Xvmax);
    Ksta = 3.14159 * Frta * Ks * Sd * limit(Xta0 + xvta, 0.0, Xta0 + Xvmax);
    Kspb = 3.14159 * Frpb * Ks * Sd * limit(Xpb0 + xvpb, 0.0, Xpb0 + Xvmax);
    Kstb = 3.14159 * Frtb * Ks * Sd * limit(Xtb0 + xvtb, 0.0, Xtb0 + Xvmax);
}

void HydraulicValve416::initialize()
{
    mpPp_p = getSafeNodeDataPtr(mpPp, NodeHydraulic::Pressure);
    mpPp_q = getSafeNodeDataPtr(mpPp, NodeHydraulic::Flow);
    mpPp_c = getSafeNodeDataPtr(mpPp, NodeHydraulic::WaveVariable);
    mpPp_Zc = getSafeNodeDataPtr(mpPp, NodeHydraulic::CharImpedance);
    mpPt_p = getSafeNodeDataPtr(mpPt, NodeHydraulic::Pressure);
    mpPt_q = getSafeNodeDataPtr(mpPt, NodeHydraulic::Flow);
    mpPt_c = getSafeNodeDataPtr(mpPt, NodeHydraulic::WaveVariable);
    mpPt_Zc = getSafeNodeDataPtr(mpPt, NodeHydraulic::CharImpedance);
    mpPa_p = getSafeNodeDataPtr(mpPa, NodeHydraulic::Pressure);
    mpPa_q = getSafeNodeDataPtr(mpPa, NodeHydraulic::Flow);
    mpPa_c = getSafeNodeDataPtr(mpPa, NodeHydraulic::WaveVariable);
    mpPa_Zc = getSafeNodeDataPtr(mpPa, NodeHydraulic::CharImpedance);
    mpPb_p = getSafeNodeDataPtr(mpPb, NodeHydraulic::Pressure);
    mpPb_q = getSafeNodeDataPtr(mpPb, NodeHydraulic::Flow);
    mpPb_c = getSafeNodeDataPtr(mpPb, NodeHydraulic::WaveVariable);
    mpPb_Zc = getSafeNodeDataPtr(mpPb, NodeHydraulic::CharImpedance);

    pp = *mpPp_p; qp = *mpPp_q; cp = *mpPp_c; Zcp = *mpPp_Zc;
    pt = *mpPt_p; qt = *mpPt_q; ct = *mpPt_c; Zct = *mpPt_Zc;
    pa = *mpPa_p; qa = *mpPa_q; ca = *mpPa_c; Zca = *mpPa_Zc;
    pb = *mpPb_p; qb = *mpPb_q; cb = *mpPb_c; Zcb = *mpPb_Zc;
    xvpa = *mp_xvpa;
    xvta = *mp_xvta;
    xvpb = *mp_xvpb;
    xvtb = *mp_xvtb;
    rho = *mp_rho;
    Cq = *mp_Cq;
    Sd = *mp_Sd;
    Frpa = *mp_Frpa;
    Frta = *mp_Frta;
    Frpb = *mp_Frpb;
    Frtb = *mp_Frtb;
    Xpa0 = *mp_Xpa0;
    Xta0 = *mp_Xta0;
    Xpb0 = *mp_Xpb0;
    Xtb0 = *mp_Xtb0;
    Xvmax = *mp_Xvmax;
    plam = *mp_plam;
    localExpressions();
}

void HydraulicValve416::simulateOneTimestep()
{
    cp = *mpPp_c; Zcp = *mpPp_Zc;
    ct = *mpPt_c; Zct = *mpPt_Zc;
    ca = *mpPa_c; Zca = *mpPa_Zc;
    cb = *mpPb_c; Zcb = *mpPb_Zc;
    xvpa = *mp_xvpa;
    xvta = *mp_xvta;
    xvpb = *mp_xvpb;
    xvtb = *mp_xvtb;
    localExpressions();

    mX[0] = qp; mX[1] = qt; mX[2] = qa; mX[3] = qb; mX[4] = pp; mX[5] = pt; mX[6] = pa; mX[7] = pb;
    for (int iter = 1; iter <= 2; ++iter) {
        const double Spa = signedSquareL(pp - pa, plam);
        const double Sta = signedSquareL(pt - pa, plam);
        const double Spb = signedSquareL(pp - pb, plam);
        const double Stb = signedSquareL(pt - pb, plam);
        const double dSpa = dxSignedSquareL(pp - pa, plam);
        const double dSta = dxSignedSquareL(pt - pa, plam);
        const double dSpb = dxSignedSquareL(pp - pb, plam);
        const double dStb = dxSignedSquareL(pt - pb, plam);
        const double ap = cp + qp * Zcp * onPositive(pp);
        const double at = ct + qt * Zct * onPositive(pt);
        const double aa = ca + qa * Zca * onPositive(pa);
        const double ab = cb + qb * Zcb * onPositive(pb);

        mF[0] = qp + Kspa * Spa + Kspb * Spb;
        mF[1] = qt + Ksta * Sta + Kstb * Stb;
        mF[2] = qa - Kspa * Spa - Ksta * Sta;
        mF[3] = qb - Kspb * Spb - Kstb * Stb;
        mF[4] = pp - lowLimit(ap, 0.0);
        mF[5] = pt - lowLimit(at, 0.0);
        mF[6] = pa - lowLimit(aa, 0.0);
        mF[7] = pb - lowLimit(ab, 0.0);

        mJ[0][0] = 1.0;
        mJ[0][1] = 0.0;
        mJ[0][2] = 0.0;
        mJ[0][3] = 0.0;
        mJ[0][4] = Kspa * dSpa + Kspb * dSpb;
        mJ[0][5] = 0.0;
        mJ[0][6] = -Kspa * dSpa;
        mJ[0][7] = -Kspb * dSpb;
        mJ[1][0] = 0.0;
        mJ[1][1] = 1.0;
        mJ[1][2] = 0.0;
        mJ[1][3] = 0.0;
        mJ[1][4] = 0.0;
        mJ[1][5] = Ksta * dSta + Kstb * dStb;
        mJ[1][6] = -Ksta * dSta;
        mJ[1][7] = -Kstb * dStb;
        mJ[2][0] = 0.0;
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[2][4] = -Kspa * dSpa;
        mJ[2][5] = -Ksta * dSta;
        mJ[2][6] = Kspa * dSpa + Ksta * dSta;
        mJ[2][7] = 0.0;
        mJ[3][0] = 0.0;
        mJ[3][1] = 0.0;
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;
        mJ[3][4] = -Kspb * dSpb;
        mJ[3][5] = -Kstb * dStb;
        mJ[3][6] = 0.0;
        mJ[3][7] = Kspb * dSpb + Kstb * dStb;
        mJ[4][0] = -Zcp * dxLowLimit(ap, 0.0) * onPositive(pp);
        mJ[4][1] = 0.0;
        mJ[4][2] = 0.0;
        mJ[4][3] = 0.0;
        mJ[4][4] = 1.0;
        mJ[4][5] = 0.0;
        mJ[4][6] = 0.0;
        mJ[4][7] = 0.0;
        mJ[5][0] = 0.0;
        mJ[5][1] = -Zct * dxLowLimit(at, 0.0) * onPositive(pt);
        mJ[5][2] = 0.0;
        mJ[5][3] = 0.0;
        mJ[5][4] = 0.0;
        mJ[5][5] = 1.0;
        mJ[5][6] = 0.0;
        mJ[5][7] = 0.0;
        mJ[6][0] = 0.0;
        mJ[6][1] = 0.0;
        mJ[6][2] = -Zca * dxLowLimit(aa, 0.0) * onPositive(pa);
        mJ[6][3] = 0.0;
        mJ[6][4] = 0.0;
        mJ[6][5] = 0.0;
        mJ[6][6] = 1.0;
        mJ[6][7] = 0.0;
        mJ[7][0] = 0.0;
        mJ[7][1] = 0.0;
        mJ[7][2] = 0.0;
        mJ[7][3] = -Zcb * dxLowLimit(ab, 0.0) * onPositive(pb);
        mJ[7][4] = 0.0;
        mJ[7][5] = 0.0;
        mJ[7][6] = 0.0;
        mJ[7][7] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicValve416: singular Jacobian");
        }
        qp = mX[0]; qt = mX[1]; qa = mX[2]; qb = mX[3]; pp = mX[4]; pt = mX[5]; pa = mX[6]; pb = mX[7];
    }

    *mpPp_p = pp;
    *mpPp_q = qp;
    *mpPt_p = pt;
    *mpPt_q = qt;
    *mpPa_p = pa;
    *mpPa_q = qa;
    *mpPb_p = pb;
    *mpPb_q = qb;
}

TLMHUB_REGISTER_COMPONENT(HydraulicValve416, "Hydraulic")

} // namespace tlmhub
