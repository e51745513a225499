#pragma once
#include "core/Component.h"

namespace tlmhub {

// Joins a 2D signal node to two scalar signal nodes, each dimension in the direction its
// scalar side asks for: a scalar port (v1 or v2) directly connected to a write port feeds
// its slot of P2d (v0 or v1); any other scalar port receives that slot. All three ports
// are bidirectional and carry no sort hint, so the component's place in the step is its
// place in the model (Hopsan's behaviour).
class Signal2DSplit : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP2d = nullptr;
    Port* mpV1 = nullptr;
    Port* mpV2 = nullptr;
    // Each dimension copies *from to *to, the direction chosen in initialize().
    double* mpFrom1 = nullptr;
    double* mpTo1 = nullptr;
    double* mpFrom2 = nullptr;
    double* mpTo2 = nullptr;
};

} // namespace tlmhub
