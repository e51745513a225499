#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// Maximum of any number of signals (a NaN in the first input propagates, later NaNs are skipped).
class SignalMax : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpIn = nullptr;
    std::vector<double*> mIn;
    double* mpOut = nullptr;
};

} // namespace tlmhub
