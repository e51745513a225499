#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Half-cosine transition from y_0 to y_0 + y_A between t_start and t_end.
class SignalSoftStep : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpTStart = nullptr;
    double* mpTEnd = nullptr;
    double* mpY0 = nullptr;
    double* mpYA = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
