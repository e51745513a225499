#pragma once
#include "core/Component.h"

#include <string>

namespace tlmhub {

// out = in1 / in2. A zero denominator gives 0 with a warning at t0, and stops the run during stepping.
class SignalDivide : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn1 = nullptr;
    double* mpIn2 = nullptr;
    double* mpOut = nullptr;
    std::string mStopMessage;
};

} // namespace tlmhub
