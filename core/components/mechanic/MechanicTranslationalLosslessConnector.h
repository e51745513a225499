#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"

namespace tlmhub {

// Q-type massless rigid connection between two translational ports (v1 = -v2).
class MechanicTranslationalLosslessConnector : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mLength = 0.0;
    double *mpP1_f = nullptr, *mpP1_x = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr;
    double *mpP2_f = nullptr, *mpP2_x = nullptr, *mpP2_v = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr;
    Integrator mIntegrator;
};

} // namespace tlmhub
