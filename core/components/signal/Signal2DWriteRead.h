#pragma once
#include "core/Component.h"

namespace tlmhub {

// One end of a two-way 2D signal link: writes its input `write` into slot v0 of the
// bidirectional port P2d and reads slot v1 back as its output `read`. Pairs with
// Signal2DReadWrite, which fills v1. P2d is the sort source of the node, so the partner
// runs after this component within a step.
class Signal2DWriteRead : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP2d = nullptr;
    double* mpWrite = nullptr;   // input variable "write"
    double* mpRead = nullptr;    // output variable "read"
    double* mpV0 = nullptr;
    double* mpV1 = nullptr;
};

} // namespace tlmhub
