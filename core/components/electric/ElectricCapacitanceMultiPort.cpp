#include "core/components/electric/ElectricCapacitanceMultiPort.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricCapacitanceMultiPort::configure()
{
    mpPel1 = addPowerMultiPort("Pel1", NodeType::Electric);
    addConstant("Capacitance", "Capacitance", "Fa", 1.0e-4, mCapacitance);
    addInputVariable("alpha", "Low pass coefficient", "", 0.3, &mpAlpha);
    setDefaultStartValue(mpPel1, NodeElectric::Current, 0.0);
    setDefaultStartValue(mpPel1, NodeElectric::Voltage, 12.0);
}

void ElectricCapacitanceMultiPort::initialize()
{
    mN = getNumPorts(mpPel1);
    mvpI.assign(mN, nullptr);
    mvpC.assign(mN, nullptr);
    mvpZc.assign(mN, nullptr);
    mvC0.assign(mN, 0.0);

    const double N = static_cast<double>(mN);
    // Hopsan quirk: Zc uses the initial alpha and is never updated.
    mZc = N * mTimestep / (2.0 * mCapacitance) / (1.0 - *mpAlpha);
    const double u0 = getDefaultStartValue(mpPel1, NodeElectric::Voltage);
    const double i0 = getDefaultStartValue(mpPel1, NodeElectric::Current);
    for (std::size_t k = 0; k < mN; ++k) {
        mvpI[k] = getSafeMultiPortNodeDataPtr(mpPel1, k, NodeElectric::Current);
        mvpC[k] = getSafeMultiPortNodeDataPtr(mpPel1, k, NodeElectric::WaveVariable);
        mvpZc[k] = getSafeMultiPortNodeDataPtr(mpPel1, k, NodeElectric::CharImpedance);
        *getSafeMultiPortNodeDataPtr(mpPel1, k, NodeElectric::Voltage) = u0;
        *mvpI[k] = i0 / N;
        *mvpC[k] = u0;
        *mvpZc[k] = mZc;
    }
}

void ElectricCapacitanceMultiPort::simulateOneTimestep()
{
    const double alpha = *mpAlpha;
    double cTot = 0.0;
    for (std::size_t k = 0; k < mN; ++k) {
        cTot += *mvpC[k] + 2.0 * mZc * *mvpI[k];
    }
    const double uAvg = cTot / static_cast<double>(mN);
    for (std::size_t k = 0; k < mN; ++k) {
        mvC0[k] = 2.0 * uAvg - *mvpC[k] - 2.0 * mZc * *mvpI[k];
        *mvpC[k] = alpha * *mvpC[k] + (1.0 - alpha) * mvC0[k];
        *mvpZc[k] = mZc;
    }
}

TLMHUB_REGISTER_COMPONENT(ElectricCapacitanceMultiPort, "Electric")

} // namespace tlmhub
