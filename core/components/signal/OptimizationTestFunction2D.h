#pragma once
#include "core/Component.h"

namespace tlmhub {

// out = f(x, y) for one of nineteen two-dimensional optimisation benchmarks, chosen by the
// constant `function` (Ackley's function first, the three-hump camel last).
class OptimizationTestFunction2D : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpX = nullptr;
    double* mpY = nullptr;
    double* mpOut = nullptr;
    int mFunction = 0;
};

} // namespace tlmhub
