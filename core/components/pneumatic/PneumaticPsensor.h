#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal-type pressure sensor: copies one node variable to a signal output.
class PneumaticPsensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPp1 = nullptr;
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
