#include "core/components/hydraulic/HydraulicOrificeG.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void HydraulicOrificeG::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    addInputVariable("rho", "Oil density", "kg/m^3", 870.0, &mpRho);
    addInputVariable("visc", "Dynamic viscosity", "Pa s", 0.12, &mpVisc);
    addInputVariable("Ao", "Orifice area", "m^2", 1e-7, &mpAo);
    addInputVariable("dh", "Hydraulic diameter", "m", 0.0025, &mpDh);
    addInputVariable("lo", "Orifice length", "m", 0.001, &mpLo);
    addInputVariable("Cdt", "Turbulent discharge coefficient", "", 0.611, &mpCdt);
    addInputVariable("del", "Laminar flow coefficient", "", 0.157, &mpDel);
    addInputVariable("sf", "Shape factor (1 round, 0 rectangular)", "", 0.0, &mpSf);
    addOutputVariable("Ro", "Reynolds number", "", 0.0, &mpRo);
    addOutputVariable("DRL", "dh*Ro/lo type number", "", 0.0, &mpDRL);
    addOutputVariable("Cd", "Effective discharge coefficient", "", 0.611, &mpCd);
}

void HydraulicOrificeG::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_dE = getSafeNodeDataPtr(mpP1, NodeHydraulic::HeatFlow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_dE = getSafeNodeDataPtr(mpP2, NodeHydraulic::HeatFlow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);

    // Newton starts from the node values (the C-side start values).
    mP1 = *mpP1_p;
    mP2 = *mpP2_p;
    mQ2 = *mpP2_q;
    mDE1 = *mpP1_dE;
    mDE2 = *mpP2_dE;

    simulateOneTimestep();
}

void HydraulicOrificeG::simulateOneTimestep()
{
    const double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    const double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double rho = *mpRho;
    const double visc = *mpVisc;
    const double Ao = *mpAo;
    const double dh = *mpDh;
    const double lo = *mpLo;
    const double Cdt = *mpCdt;
    const double del = *mpDel;
    const double sf = *mpSf;

    mX[0] = mQ2;
    mX[1] = mP1;
    mX[2] = mP2;

    for (int iter = 1; iter <= 2; ++iter) {
        const double q2 = mX[0], p1 = mX[1], p2 = mX[2];
        const double S = (std::pow(Cdt, 2) * std::pow(dh - 32 * std::pow(del, 2) * lo * (sf - 3), 2) * std::pow(visc, 2)
                          + 2 * std::pow(del, 4) * std::pow(dh, 4) * rho * std::fabs(p1 - p2))
                         / (std::pow(Ao, 2) * std::pow(Cdt, 2) * std::pow(del, 4) * std::pow(dh, 4));
        mF[0] = q2 - 2 * (p1 - p2) / std::sqrt(S);
        mF[1] = p1 - lowLimit(c1 - q2 * Zc1, 0);
        mF[2] = p2 - lowLimit(c2 + q2 * Zc2, 0);

        const double G = 2 * (p1 - p2) * rho * dxAbs(p1 - p2) / (std::pow(Ao, 2) * std::pow(Cdt, 2) * std::pow(S, 1.5));
        mJ[0][0] = 1;
        mJ[0][1] = -2 / std::sqrt(S) + G;
        mJ[0][2] = 2 / std::sqrt(S) - G;
        mJ[1][0] = Zc1 * dxLowLimit(c1 - q2 * Zc1, 0);
        mJ[1][1] = 1;
        mJ[1][2] = 0;
        mJ[2][0] = -(Zc2 * dxLowLimit(c2 + q2 * Zc2, 0));
        mJ[2][1] = 0;
        mJ[2][2] = 1;

        mSolver.solve(mJ, mF, mX, iter);
        mQ2 = mX[0];
        mP1 = mX[1];
        mP2 = mX[2];
    }

    const double q1 = -mQ2;
    const double Ro = dh * rho * std::fabs(mQ2) / (Ao * visc);
    const double DRL = dh * Ro / (0.1 * dh + lo);
    const double Cd = std::fabs(mQ2) / (std::sqrt(2) * Ao * std::sqrt((0.1 + std::fabs(mP1 - mP2)) / rho));

    *mpP1_p = mP1;
    *mpP1_q = q1;
    *mpP1_dE = mDE1;
    *mpP2_p = mP2;
    *mpP2_q = mQ2;
    *mpP2_dE = mDE2;
    *mpRo = Ro;
    *mpDRL = DRL;
    *mpCd = Cd;
}

TLMHUB_REGISTER_COMPONENT(HydraulicOrificeG, "Hydraulic")

} // namespace tlmhub
