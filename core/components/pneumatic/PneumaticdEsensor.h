#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal-type energy-flow sensor: copies one node variable to a signal output.
class PneumaticdEsensor : public ComponentSignal {
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
