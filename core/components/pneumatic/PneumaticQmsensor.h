#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal-type mass-flow sensor: copies one node variable to a signal output.
class PneumaticQmsensor : public ComponentSignal {
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
