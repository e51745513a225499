#pragma once
#include "core/Component.h"

namespace tlmhub {

// Packs two scalar signals into one two-dimensional signal node: P2d.v0 = in1, P2d.v1 = in2.
class Signal2DWrite : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP2d = nullptr;
    double* mpIn1 = nullptr;
    double* mpIn2 = nullptr;
    double* mpV0 = nullptr;
    double* mpV1 = nullptr;
};

} // namespace tlmhub
