#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A electric boundary of Q type: the node's effort and flow come from outside.
using ElectricInterfaceQ = PowerInterface<ComponentQ, NodeType::Electric>;

TLMHUB_REGISTER_COMPONENT(ElectricInterfaceQ, "Connectivity")

} // namespace tlmhub
