#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type tank: constant pressure with zero impedance.
class HydraulicTankC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override {}

private:
    Port* mpP1 = nullptr;
    double mP = 1.0e5;
};

} // namespace tlmhub
