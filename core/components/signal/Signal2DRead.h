#pragma once
#include "core/Component.h"

namespace tlmhub {

// Unpacks a two-dimensional signal node into two scalar signals: out1 = P2d.v0, out2 = P2d.v1.
class Signal2DRead : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP2d = nullptr;
    double* mpV0 = nullptr;
    double* mpV1 = nullptr;
    double* mpOut1 = nullptr;
    double* mpOut2 = nullptr;
};

} // namespace tlmhub
