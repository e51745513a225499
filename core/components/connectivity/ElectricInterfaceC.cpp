#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A electric boundary of C type: the node's wave variable and impedance come from outside.
using ElectricInterfaceC = PowerInterface<ComponentC, NodeType::Electric>;

TLMHUB_REGISTER_COMPONENT(ElectricInterfaceC, "Connectivity")

} // namespace tlmhub
