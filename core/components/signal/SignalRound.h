#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// out = round(in), halves away from zero (C round, not banker's rounding).
class SignalRound : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
