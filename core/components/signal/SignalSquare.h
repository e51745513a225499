#pragma once
#include "core/Component.h"

namespace tlmhub {

// out = in * in.
class SignalSquare : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
