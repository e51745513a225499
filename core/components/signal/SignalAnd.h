#pragma once
#include "core/Component.h"

namespace tlmhub {

// Logical AND: inputs are true when > 0.5.
class SignalAnd : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn1 = nullptr;
    double* mpIn2 = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
