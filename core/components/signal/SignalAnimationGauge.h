#pragma once
#include "core/Component.h"

namespace tlmhub {

// GUI gauge: displays its input, computes nothing in batch runs.
class SignalAnimationGauge : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double mMax = 1.0;
};

} // namespace tlmhub
