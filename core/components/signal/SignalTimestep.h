#pragma once
#include "core/Component.h"

namespace tlmhub {

// Outputs the time step of the system the component runs in.
class SignalTimestep : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpTs = nullptr;
};

} // namespace tlmhub
