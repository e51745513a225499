#pragma once
#include "core/Component.h"

namespace tlmhub {

// GUI lamp indicator: computes nothing in batch runs.
class SignalAnimationLamp : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
};

} // namespace tlmhub
