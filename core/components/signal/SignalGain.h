#pragma once
#include "core/Component.h"

namespace tlmhub {

// out = k * in. Older files give the gain as plain `k`, which the loader maps to k#Value.
class SignalGain : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpK = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
