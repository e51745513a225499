#include "core/components/hydraulic/HydraulicValve33.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicValve33::configure()
{
    mpPp = addPowerPort("Pp", NodeType::Hydraulic);
    mpPt = addPowerPort("Pt", NodeType::Hydraulic);
    mpPa = addPowerPort("Pa", NodeType::Hydraulic);

    addInputVariable("xv", "Spool position", "m", 0.0, &mp_xv);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mp_rho);
    addInputVariable("Cq", "Flow coefficient", "-", 0.67, &mp_Cq);
    addInputVariable("Sd", "Spool diameter", "m", 0.01, &mp_Sd);
    addInputVariable("Frap", "Circumference fraction P-A", "-", 1.0, &mp_Frap);
    addInputVariable("Frat", "Circumference fraction A-T", "-", 1.0, &mp_Frat);
    addInputVariable("Xap0", "Underlap P-A", "m", 0.0, &mp_Xap0);
    addInputVariable("Xat0", "Underlap A-T", "m", 0.0, &mp_Xat0);
    addInputVariable("Xvmax", "Maximum opening", "m", 0.01, &mp_Xvmax);
    addInputVariable("plam", "Turbulence onset pressure", "Pa", 1.0e4, &mp_plam);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rho", "Cq", "Sd", "Frap", "Frat", "Xap0", "Xat0", "Xvmax", "plam"}, false);
}

void HydraulicValve33::localExpressions()
{
    Ks = 1.4142135623730951 * Cq / std::sqrt(rho);
    Kspa = 3.14159 * Frap * Ks * Sd * limit(Xap0 + xv, 0.0, Xap0 + Xvmax);
    // The A-T opening uses Xap0 inside the limit (reference quirk).
    Ksta = 3.14159 * Frat * Ks * Sd * limit(Xap0 - xv, 0.0, Xat0 + Xvmax);
}

void HydraulicValve33::initialize()
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

    pp = *mpPp_p; qp = *mpPp_q; cp = *mpPp_c; Zcp = *mpPp_Zc;
    pt = *mpPt_p; qt = *mpPt_q; ct = *mpPt_c; Zct = *mpPt_Zc;
    pa = *mpPa_p; qa = *mpPa_q; ca = *mpPa_c; Zca = *mpPa_Zc;
    xv = *mp_xv;
    rho = *mp_rho;
    Cq = *mp_Cq;
    Sd = *mp_Sd;
    Frap = *mp_Frap;
    Frat = *mp_Frat;
    Xap0 = *mp_Xap0;
    Xat0 = *mp_Xat0;
    Xvmax = *mp_Xvmax;
    plam = *mp_plam;
    localExpressions();
}

void HydraulicValve33::simulateOneTimestep()
{
    cp = *mpPp_c; Zcp = *mpPp_Zc;
    ct = *mpPt_c; Zct = *mpPt_Zc;
    ca = *mpPa_c; Zca = *mpPa_Zc;
    xv = *mp_xv;
    localExpressions();

    mX[0] = qp; mX[1] = qt; mX[2] = qa; mX[3] = pp; mX[4] = pt; mX[5] = pa;
    for (int iter = 1; iter <= 2; ++iter) {
        const double Spa = signedSquareL(pp - pa, plam);
        const double Sta = signedSquareL(pt - pa, plam);
        const double dSpa = dxSignedSquareL(pp - pa, plam);
        const double dSta = dxSignedSquareL(pt - pa, plam);
        const double ap = cp + qp * Zcp * onPositive(pp);
        const double at = ct + qt * Zct * onPositive(pt);
        const double aa = ca + qa * Zca * onPositive(pa);

        mF[0] = qp + Kspa * Spa;
        mF[1] = qt + Ksta * Sta;
        mF[2] = qa - Kspa * Spa - Ksta * Sta;
        mF[3] = pp - lowLimit(ap, 0.0);
        mF[4] = pt - lowLimit(at, 0.0);
        mF[5] = pa - lowLimit(aa, 0.0);

        mJ[0][0] = 1.0;
        mJ[0][1] = 0.0;
        mJ[0][2] = 0.0;
        mJ[0][3] = Kspa * dSpa;
        mJ[0][4] = 0.0;
        mJ[0][5] = -Kspa * dSpa;
        mJ[1][0] = 0.0;
        mJ[1][1] = 1.0;
        mJ[1][2] = 0.0;
        mJ[1][3] = 0.0;
        mJ[1][4] = Ksta * dSta;
        mJ[1][5] = -Ksta * dSta;
        mJ[2][0] = 0.0;
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;
        mJ[2][3] = -Kspa * dSpa;
        mJ[2][4] = -Ksta * dSta;
        mJ[2][5] = Kspa * dSpa + Ksta * dSta;
        mJ[3][0] = -Zcp * dxLowLimit(ap, 0.0) * onPositive(pp);
        mJ[3][1] = 0.0;
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;
        mJ[3][4] = 0.0;
        mJ[3][5] = 0.0;
        mJ[4][0] = 0.0;
        mJ[4][1] = -Zct * dxLowLimit(at, 0.0) * onPositive(pt);
        mJ[4][2] = 0.0;
        mJ[4][3] = 0.0;
        mJ[4][4] = 1.0;
        mJ[4][5] = 0.0;
        mJ[5][0] = 0.0;
        mJ[5][1] = 0.0;
        mJ[5][2] = -Zca * dxLowLimit(aa, 0.0) * onPositive(pa);
        mJ[5][3] = 0.0;
        mJ[5][4] = 0.0;
        mJ[5][5] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicValve33: singular Jacobian");
        }
        qp = mX[0]; qt = mX[1]; qa = mX[2]; pp = mX[3]; pt = mX[4]; pa = mX[5];
    }

    *mpPp_p = pp;
    *mpPp_q = qp;
    *mpPt_p = pt;
    *mpPt_q = qt;
    *mpPa_p = pa;
    *mpPa_q = qa;
}

TLMHUB_REGISTER_COMPONENT(HydraulicValve33, "Hydraulic")

} // namespace tlmhub
