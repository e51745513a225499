#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// out = cos(in).
class SignalCos : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
