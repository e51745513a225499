#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal benchmark load generator: a CPU-burning loop with no physical meaning.
class SignalDummy : public ComponentSignal {
public:
    void configure() override;
    void simulateOneTimestep() override;

private:
    double *mpIn = nullptr, *mpOut = nullptr;
};

} // namespace tlmhub
