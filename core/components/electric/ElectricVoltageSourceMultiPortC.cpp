#include "core/components/electric/ElectricVoltageSourceMultiPortC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricVoltageSourceMultiPortC::configure()
{
    mpP1 = addPowerMultiPort("P1", NodeType::Electric);
    addInputVariable("U", "Voltage", "V", 12.0, &mpU);
    // Only the current start value is user-settable.
    disableStartValue(mpP1, NodeElectric::Voltage);
    disableStartValue(mpP1, NodeElectric::WaveVariable);
    disableStartValue(mpP1, NodeElectric::CharImpedance);
}

void ElectricVoltageSourceMultiPortC::initialize()
{
    const std::size_t n = getNumPorts(mpP1);
    mvpC.assign(n, nullptr);
    mvpZc.assign(n, nullptr);
    const double U = *mpU;
    const double i0 = getDefaultStartValue(mpP1, NodeElectric::Current);
    for (std::size_t k = 0; k < n; ++k) {
        mvpC[k] = getSafeMultiPortNodeDataPtr(mpP1, k, NodeElectric::WaveVariable);
        mvpZc[k] = getSafeMultiPortNodeDataPtr(mpP1, k, NodeElectric::CharImpedance);
        *getSafeMultiPortNodeDataPtr(mpP1, k, NodeElectric::Voltage) = U;
        *getSafeMultiPortNodeDataPtr(mpP1, k, NodeElectric::Current) = i0;
        *mvpC[k] = U;
        *mvpZc[k] = 0.0;
    }
}

void ElectricVoltageSourceMultiPortC::simulateOneTimestep()
{
    const double U = *mpU;
    for (std::size_t k = 0; k < mvpC.size(); ++k) {
        *mvpC[k] = U;
        *mvpZc[k] = 0.0;
    }
}

TLMHUB_REGISTER_COMPONENT(ElectricVoltageSourceMultiPortC, "Electric")

} // namespace tlmhub
