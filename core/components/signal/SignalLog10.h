#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Base-10 logarithm; non-positive input gives 0 and raises `error`.
class SignalLog10 : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double* mpError = nullptr;
};

} // namespace tlmhub
