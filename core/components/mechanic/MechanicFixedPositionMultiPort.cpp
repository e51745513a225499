#include "core/components/mechanic/MechanicFixedPositionMultiPort.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicFixedPositionMultiPort::configure()
{
    mpPm1 = addPowerMultiPort("Pm1", NodeType::Mechanic);
    addConstant("m_e", "Equivalent mass", "kg", 1.0, mMe);
}

void MechanicFixedPositionMultiPort::initialize()
{
    const std::size_t n = getNumPorts(mpPm1);
    mF.assign(n, nullptr);
    mC.assign(n, nullptr);
    for (std::size_t i = 0; i < n; ++i) {
        mF[i] = getSafeMultiPortNodeDataPtr(mpPm1, i, NodeMechanic::Force);
        mC[i] = getSafeMultiPortNodeDataPtr(mpPm1, i, NodeMechanic::WaveVariable);
        *getSafeMultiPortNodeDataPtr(mpPm1, i, NodeMechanic::Velocity) = 0.0;
        *getSafeMultiPortNodeDataPtr(mpPm1, i, NodeMechanic::EquivalentMass) = mMe;
    }
}

void MechanicFixedPositionMultiPort::simulateOneTimestep()
{
    for (std::size_t i = 0; i < mF.size(); ++i) {
        *mF[i] = *mC[i];
    }
}

TLMHUB_REGISTER_COMPONENT(MechanicFixedPositionMultiPort, "Mechanic")

} // namespace tlmhub
