#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal sensor: copies the force of a translational node to the output signal.
class MechanicForceSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpP1_val = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
