#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Periodic pulse train with period dT and duty cycle D, starting high at t_start.
class SignalPulseWave : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpY0 = nullptr;
    double* mpYA = nullptr;
    double* mpTStart = nullptr;
    double* mpDT = nullptr;
    double* mpD = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
