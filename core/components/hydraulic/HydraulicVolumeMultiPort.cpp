#include "core/components/hydraulic/HydraulicVolumeMultiPort.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicVolumeMultiPort::configure()
{
    mpP1 = addPowerMultiPort("P1", NodeType::Hydraulic);
    addConstant("P_high", "High pressure (for animation)", "Pa", 2e7, mPhigh);
    addInputVariable("V", "Volume", "m^3", 1.0e-3, &mpV);
    addInputVariable("Beta_e", "Bulkmodulus", "Pa", 1.0e9, &mpBetae);
    addInputVariable("alpha", "Low pass coefficient to dampen standing waves", "", 0.1, &mpAlpha);

    setDefaultStartValue(mpP1, NodeHydraulic::Flow, 0.0);
    setDefaultStartValue(mpP1, NodeHydraulic::Pressure, 1.0e5);
}

void HydraulicVolumeMultiPort::initialize()
{
    mNumPorts = getNumPorts(mpP1);
    mP1.resize(mNumPorts);

    const double N = static_cast<double>(mNumPorts);
    const double V = *mpV;
    const double betae = *mpBetae;
    const double alpha = *mpAlpha;
    const double Zc = N * betae / (2.0 * V) * mTimestep / (1.0 - alpha);

    // Every sub-port uses the single start value set of the multiport.
    const double p0 = getDefaultStartValue(mpP1, NodeHydraulic::Pressure);
    const double q0 = getDefaultStartValue(mpP1, NodeHydraulic::Flow);

    double pTot = 0.0;
    for (std::size_t i = 0; i < mNumPorts; ++i) {
        mP1[i].p = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::Pressure);
        mP1[i].q = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::Flow);
        mP1[i].c = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::WaveVariable);
        mP1[i].Zc = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::CharImpedance);

        *mP1[i].p = p0;
        *mP1[i].q = q0;
        pTot += p0 + Zc * q0;
        *mP1[i].Zc = Zc;
    }
    pTot = pTot / N;
    for (std::size_t i = 0; i < mNumPorts; ++i) {
        *mP1[i].c = 2.0 * pTot - (*mP1[i].p) - Zc * (*mP1[i].q);
    }
}

void HydraulicVolumeMultiPort::simulateOneTimestep()
{
    const double N = static_cast<double>(mNumPorts);
    const double V = *mpV;
    const double betae = *mpBetae;
    const double alpha = *mpAlpha;
    // Zc follows the (signal) inputs every step.
    const double Zc = N * betae / (2.0 * V) * mTimestep / (1.0 - alpha);

    double cTot = 0.0;
    for (std::size_t i = 0; i < mNumPorts; ++i) {
        cTot += (*mP1[i].c) + 2.0 * Zc * (*mP1[i].q);
    }
    const double pAvg = cTot / N;

    // Each new c_i depends only on its own old c_i, so updating in place is safe.
    for (std::size_t i = 0; i < mNumPorts; ++i) {
        const double ci = *mP1[i].c;
        const double c0 = 2.0 * pAvg - ci - 2.0 * Zc * (*mP1[i].q);
        *mP1[i].Zc = Zc;
        *mP1[i].c = alpha * ci + (1.0 - alpha) * c0;
    }
}

TLMHUB_REGISTER_COMPONENT(HydraulicVolumeMultiPort, "Hydraulic")

} // namespace tlmhub
