#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// Sum of the insum signals minus the sum of the insub signals, in connection order.
class SignalSub : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpInSum = nullptr;
    Port* mpInSub = nullptr;
    std::vector<double*> mInSum;
    std::vector<double*> mInSub;
    double* mpOut = nullptr;
};

} // namespace tlmhub
