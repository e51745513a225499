#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// Sum of any number of signals, accumulated in connection order starting from 0.
class SignalSum : public ComponentSignal {
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
