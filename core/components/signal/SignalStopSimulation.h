#pragma once
#include "core/Component.h"

#include <string>

namespace tlmhub {

// Stops the simulation after the first step at which the input is true (> 0.5).
class SignalStopSimulation : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    std::string mMessage;
    std::string mStopText;
};

} // namespace tlmhub
