#pragma once
#include "core/Component.h"

namespace tlmhub {

// Area of the uncovered circular segment of a round hole of the given diameter.
class SignalSegare : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpX = nullptr;
    double* mpDiameter = nullptr;
    double* mpArea = nullptr;
};

} // namespace tlmhub
