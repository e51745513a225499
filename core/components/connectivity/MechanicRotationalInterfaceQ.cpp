#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A rotational mechanic boundary of Q type: the node's effort and flow come from outside.
using MechanicRotationalInterfaceQ = PowerInterface<ComponentQ, NodeType::MechanicRotational>;

TLMHUB_REGISTER_COMPONENT(MechanicRotationalInterfaceQ, "Connectivity")

} // namespace tlmhub
