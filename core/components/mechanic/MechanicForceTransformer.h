#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type ideal force source: the input force is imposed as a zero-impedance wave.
class MechanicForceTransformer : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpF = nullptr;
    double *mpP1_f = nullptr, *mpP1_c = nullptr;
};

} // namespace tlmhub
