#pragma once
#include "core/Component.h"

namespace tlmhub {

// The other end of a two-way 2D signal link: reads slot v0 of the bidirectional port P2d
// as its output `read` and writes its input `write` into slot v1. Pairs with
// Signal2DWriteRead.
//
// Sorting: P2d is a destination by default (sh2d = 0), so this component runs after the
// Signal2DWriteRead that writes v0 and passes this step's value on. With sh2d = 1
// ("IndependentDestination") it reads v0 as left by the previous step, which lets a
// model close a loop through the pair. The input `write` never orders this component: its
// value only reaches the partner's output, one step later at the earliest.
class Signal2DReadWrite : public ComponentSignal {
public:
    void configure() override;
    void preInitialize() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP2d = nullptr;
    int mSortHintChoice = 0;     // sh2d: 0 Destination, 1 IndependentDestination
    double* mpRead = nullptr;    // output variable "read"
    double* mpWrite = nullptr;   // input variable "write"
    double* mpV0 = nullptr;
    double* mpV1 = nullptr;
};

} // namespace tlmhub
