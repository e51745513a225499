#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Arc cosine; inputs outside [-1, 1] are clamped and flagged on `error`.
class SignalAcos : public ComponentSignal {
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
