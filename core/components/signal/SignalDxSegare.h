#pragma once
#include "core/Component.h"

namespace tlmhub {

// Derivative of the circular segment area with respect to the opening (chord width).
class SignalDxSegare : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpX = nullptr;
    double* mpDiameter = nullptr;
    double* mpWidth = nullptr;
};

} // namespace tlmhub
