#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A hydraulic boundary of C type: the node's wave variable and impedance come from outside.
using HydraulicInterfaceC = PowerInterface<ComponentC, NodeType::Hydraulic>;

TLMHUB_REGISTER_COMPONENT(HydraulicInterfaceC, "Connectivity")

} // namespace tlmhub
