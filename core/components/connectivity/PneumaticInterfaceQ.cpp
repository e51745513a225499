#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A pneumatic boundary of Q type: the node's effort and flow come from outside.
using PneumaticInterfaceQ = PowerInterface<ComponentQ, NodeType::Pneumatic>;

TLMHUB_REGISTER_COMPONENT(PneumaticInterfaceQ, "Connectivity")

} // namespace tlmhub
