#include "core/components/mechanic/MechanicTorqueTransformer.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicTorqueTransformer::configure()
{
    addInputVariable("T", "Generated torque", "Nm", 0.0, &mpT);
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
    // The torque is given by the input.
    disableStartValue(mpP1, NodeMechanicRotational::Torque);
}

void MechanicTorqueTransformer::initialize()
{
    mpP1_T = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::Torque);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::CharImpedance);

    *mpP1_T = *mpT;
    simulateOneTimestep();
}

void MechanicTorqueTransformer::simulateOneTimestep()
{
    *mpP1_c = *mpT;
    *mpP1_Zc = 0.0;
}

TLMHUB_REGISTER_COMPONENT(MechanicTorqueTransformer, "Mechanic")

} // namespace tlmhub
