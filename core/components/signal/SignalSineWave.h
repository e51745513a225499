#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Sine wave y_A*sin(2*pi*f*(t - t_start - y_offset)), zero before t_start.
class SignalSineWave : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpF = nullptr;
    double* mpYA = nullptr;
    double* mpYOffset = nullptr;
    double* mpTStart = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
