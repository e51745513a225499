#pragma once
#include "core/Component.h"

namespace tlmhub {

// Single rectangular pulse; edges are tested half a step ahead to be robust to time rounding.
class SignalPulse : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpY0 = nullptr;
    double* mpYA = nullptr;
    double* mpTStart = nullptr;
    double* mpTEnd = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
