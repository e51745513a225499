#pragma once
#include "core/components/hydraulic/HydraulicCylinderC.h"

namespace tlmhub {

// HydraulicCylinderC with one area input A used for both chambers.
class HydraulicSymmetricCylinderC : public HydraulicCylinderC {
public:
    void initialize() override;

protected:
    void addAreaInputs() override;
};

} // namespace tlmhub
