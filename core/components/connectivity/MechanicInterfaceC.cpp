#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A mechanic boundary of C type: the node's wave variable and impedance come from outside.
using MechanicInterfaceC = PowerInterface<ComponentC, NodeType::Mechanic>;

TLMHUB_REGISTER_COMPONENT(MechanicInterfaceC, "Connectivity")

} // namespace tlmhub
