#pragma once
#include "core/Component.h"

namespace tlmhub {

// GUI slider: maps an input in [0, 1] linearly onto [min, max].
class SignalAnimationSlider : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mMin = 0.0;
    double mMax = 1.0;
};

} // namespace tlmhub
