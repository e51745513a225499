#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Square root; negative input gives 0 and raises `error` (sqrt(0) is no error).
class SignalSqrt : public ComponentSignal {
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
