#pragma once
#include "core/Component.h"

#include <string>

namespace tlmhub {

// Ends the run after the first step at which the input is true (> 0.5): the model's designed
// end, a normal finish with the message as its reason.
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
