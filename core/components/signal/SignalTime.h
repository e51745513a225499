#pragma once
#include "core/Component.h"

namespace tlmhub {

// Outputs the component's accumulated simulation time.
class SignalTime : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpOut = nullptr;
};

} // namespace tlmhub
