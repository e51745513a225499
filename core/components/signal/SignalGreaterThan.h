#pragma once
#include "core/Component.h"

namespace tlmhub {

// Comparator on raw values: 1 when in > x_limit (equality gives 0).
class SignalGreaterThan : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpX_limit = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
