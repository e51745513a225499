#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A hydraulic boundary of Q type: the node's effort and flow come from outside.
using HydraulicInterfaceQ = PowerInterface<ComponentQ, NodeType::Hydraulic>;

TLMHUB_REGISTER_COMPONENT(HydraulicInterfaceQ, "Connectivity")

} // namespace tlmhub
