#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal-type voltage sensor: copies one node variable to a signal output.
class ElectricUsensor : public ComponentSignal {
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
