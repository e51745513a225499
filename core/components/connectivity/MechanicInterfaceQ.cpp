#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A mechanic boundary of Q type: the node's effort and flow come from outside.
using MechanicInterfaceQ = PowerInterface<ComponentQ, NodeType::Mechanic>;

TLMHUB_REGISTER_COMPONENT(MechanicInterfaceQ, "Connectivity")

} // namespace tlmhub
