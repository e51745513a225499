#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A Petri net boundary of Q type: the node's effort and flow come from outside.
using PetriNetInterfaceQ = PowerInterface<ComponentQ, NodeType::PetriNet>;

TLMHUB_REGISTER_COMPONENT(PetriNetInterfaceQ, "Connectivity")

} // namespace tlmhub
