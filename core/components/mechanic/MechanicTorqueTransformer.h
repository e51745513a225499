#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type ideal torque source: the input torque is imposed as a zero-impedance wave.
class MechanicTorqueTransformer : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpT = nullptr;
    double *mpP1_T = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
