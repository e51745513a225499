#pragma once
#include "core/Component.h"

namespace tlmhub {

// Clamps the input between y_lower and y_upper (upper test first, bounds never swapped).
class SignalSaturation : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpY_upper = nullptr;
    double* mpY_lower = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
