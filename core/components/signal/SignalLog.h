#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Natural logarithm; non-positive input gives 0 and raises `error`.
class SignalLog : public ComponentSignal {
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
