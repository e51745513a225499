#pragma once
#include "core/Component.h"

namespace tlmhub {

// Sign with sign(0) = +1 (and NaN -> -1), like the library helper.
class SignalSign : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
