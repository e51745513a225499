#pragma once
#include "core/Component.h"

namespace tlmhub {

// out = in1 - in2.
class SignalSubtract : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn1 = nullptr;
    double* mpIn2 = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
