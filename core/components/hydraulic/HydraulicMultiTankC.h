#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type tank on a multiport: every connection sees the same constant pressure.
class HydraulicMultiTankC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override {}

private:
    Port* mpMP = nullptr;
    double mP = 1.0e5;
};

} // namespace tlmhub
