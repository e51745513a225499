#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal-type current sensor: copies one node variable to a signal output.
class ElectricIsensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPel1 = nullptr;
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
