#include "core/components/hydraulic/HydraulicOrificeCheckValveG.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicOrificeCheckValveG::configure()
{
    mpPp = addPowerPort("Pp", NodeType::Hydraulic);
    mpPc = addPowerPort("Pc", NodeType::Hydraulic);

    addInputVariable("Ao", "Orifice area", "m^2", 0.0003, &mpAo);
    addInputVariable("dh", "Orifice hydraulic diameter", "m", 0.3, &mpDh);
    addInputVariable("lo", "Length", "m", 0.001, &mpLo);
    addInputVariable("rho", "oil density", "kg/m^3", 860.0, &mpRho);
    addInputVariable("visc", "Dynamic viscosity", "Ns/m^2", 0.12, &mpVisc);
    addInputVariable("Cdt", "Turbulent flow coefficient.", "", 0.67, &mpCdt);
    addInputVariable("del", "Flow coefficient.", "", 0.02, &mpDel);
    addInputVariable("Ab", "back valve area", "m^2", 0.0001, &mpAb);
    addInputVariable("dhb", "back valve hydraulic diameter (unused)", "m", 0.0001, &mpDhb);
    addOutputVariable("Ro", "Reynolds number", "", 0.0, &mpRo);
    addOutputVariable("DRL", "dh Ro/lo", "", 0.0, &mpDRL);
    addOutputVariable("Cd", "Discharge coeff", "", 0.611, &mpCd);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"dhb"}, false);
}

void HydraulicOrificeCheckValveG::initialize()
{
    mpPp_p = getSafeNodeDataPtr(mpPp, NodeHydraulic::Pressure);
    mpPp_q = getSafeNodeDataPtr(mpPp, NodeHydraulic::Flow);
    mpPp_c = getSafeNodeDataPtr(mpPp, NodeHydraulic::WaveVariable);
    mpPp_Zc = getSafeNodeDataPtr(mpPp, NodeHydraulic::CharImpedance);
    mpPc_p = getSafeNodeDataPtr(mpPc, NodeHydraulic::Pressure);
    mpPc_q = getSafeNodeDataPtr(mpPc, NodeHydraulic::Flow);
    mpPc_c = getSafeNodeDataPtr(mpPc, NodeHydraulic::WaveVariable);
    mpPc_Zc = getSafeNodeDataPtr(mpPc, NodeHydraulic::CharImpedance);

    // Newton starts from the start values; like the generated code, one step is run here.
    qp = *mpPp_q;
    pp = *mpPp_p;
    pc = *mpPc_p;
    simulateOneTimestep();
}

void HydraulicOrificeCheckValveG::simulateOneTimestep()
{
    const double cp = *mpPp_c, Zcp = *mpPp_Zc, cc = *mpPc_c, Zcc = *mpPc_Zc;
    const double Ao = *mpAo, dh = *mpDh, lo = *mpLo;
    const double rho = *mpRho, visc = *mpVisc, Cdt = *mpCdt, del = *mpDel, Ab = *mpAb;

    // q = -2*A*dp/D with D^2 = (laminar + turbulent)/(Cdt^2 del^4 dh^4): laminar for small
    // |dp|, q -> Cdt*A*sqrt(2|dp|/rho) for large |dp|.
    const double lam = Cdt * Cdt * std::pow(dh + 96.0 * del * del * lo, 2) * visc * visc;
    const double scale = Cdt * Cdt * std::pow(del, 4) * std::pow(dh, 4);
    const double turb = 2.0 * std::pow(del, 4) * std::pow(dh, 4) * rho;

    mX[0] = qp; mX[1] = pp; mX[2] = pc;
    for (int iter = 1; iter <= 2; ++iter) {
        const double A = ifPositive(pc - pp, Ao, Ab);
        const double D = std::sqrt((lam + turb * std::fabs(pc - pp)) / scale);
        const double dFdpp = 2.0 * A / D + 2.0 * (pp - pc) * rho * dxAbs(pc - pp) * A / (Cdt * Cdt * D * D * D);

        mF[0] = qp + 2.0 * (pp - pc) * A / D;
        mF[1] = pp - lowLimit(cp + qp * Zcp, 0.0);
        mF[2] = pc - lowLimit(cc - qp * Zcc, 0.0);

        mJ[0][0] = 1.0;
        mJ[0][1] = dFdpp;
        mJ[0][2] = -dFdpp;
        mJ[1][0] = -Zcp * dxLowLimit(cp + qp * Zcp, 0.0);
        mJ[1][1] = 1.0;
        mJ[1][2] = 0.0;
        mJ[2][0] = Zcc * dxLowLimit(cc - qp * Zcc, 0.0);
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("HydraulicOrificeCheckValveG: singular Jacobian");
        }
        qp = mX[0]; pp = mX[1]; pc = mX[2];
    }

    const double Ro = dh * rho * std::fabs(qp) / ((Ao + 0.01 * dh * dh) * visc);
    *mpPp_p = pp;
    *mpPp_q = qp;
    *mpPc_p = pc;
    *mpPc_q = -qp;
    *mpRo = Ro;
    *mpDRL = dh * Ro / (0.1 * dh + lo);
    *mpCd = std::fabs(qp) / (std::sqrt(2.0) * Ao * std::sqrt((0.1 + std::fabs(pc - pp)) / rho));
}

TLMHUB_REGISTER_COMPONENT(HydraulicOrificeCheckValveG, "Hydraulic")

} // namespace tlmhub
