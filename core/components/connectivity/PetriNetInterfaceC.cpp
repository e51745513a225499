#include "core/ComponentFactory.h"
#include "core/components/connectivity/PowerInterface.h"

namespace tlmhub {

// A Petri net boundary of C type: the node's wave variable and impedance come from outside.
using PetriNetInterfaceC = PowerInterface<ComponentC, NodeType::PetriNet>;

TLMHUB_REGISTER_COMPONENT(PetriNetInterfaceC, "Connectivity")

} // namespace tlmhub
