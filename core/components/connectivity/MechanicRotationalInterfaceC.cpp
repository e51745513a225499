#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A rotational mechanic boundary of C type: the node's wave variable and impedance come from outside.
using MechanicRotationalInterfaceC = PowerInterface<ComponentC, NodeType::MechanicRotational>;

TLMHUB_REGISTER_COMPONENT(MechanicRotationalInterfaceC, "Connectivity")

} // namespace tlmhub
