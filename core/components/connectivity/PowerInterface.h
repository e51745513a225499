#pragma once
#include "core/Component.h"

namespace tlmhub {

// The boundary of a model whose other side another program simulates (an exported FMU's
// power port): one power port P1 and no equations of its own. Between steps, the program
// running the model writes the node slots that its side owns and reads the others
// (fmu/ModelInterface.h says which). Base is ComponentC or ComponentQ: the kind the outside
// plays, as Hopsan's <Domain>InterfaceC / <Domain>InterfaceQ types do.
template <typename Base, NodeType Domain>
class PowerInterface : public Base {
public:
    void configure() override { this->addPowerPort("P1", Domain); }
};

} // namespace tlmhub
