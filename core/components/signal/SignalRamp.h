#pragma once
#include "core/Component.h"

namespace tlmhub {

// Linear ramp from y_0 to y_0 + y_A between t_start and t_end.
class SignalRamp : public ComponentSignal {
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
