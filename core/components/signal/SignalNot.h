#pragma once
#include "core/Component.h"

namespace tlmhub {

// Logical NOT: 1 when in <= 0.5, else 0.
class SignalNot : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
