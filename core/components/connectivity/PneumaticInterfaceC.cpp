#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A pneumatic boundary of C type: the node's wave variable and impedance come from outside.
using PneumaticInterfaceC = PowerInterface<ComponentC, NodeType::Pneumatic>;

TLMHUB_REGISTER_COMPONENT(PneumaticInterfaceC, "Connectivity")

} // namespace tlmhub
