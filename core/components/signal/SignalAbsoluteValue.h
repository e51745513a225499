#pragma once
#include "core/Component.h"

namespace tlmhub {

// Absolute value written as a branch so that -0.0 becomes +0.0.
class SignalAbsoluteValue : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
