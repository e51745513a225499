#pragma once
#include "core/Component.h"
#include "core/numerics/DoubleIntegratorWithDamping.h"

namespace tlmhub {

// Q-type mass on the P2 side of a lever; P1 motion is scaled by 1/w, w = (L_1+L_2)/L_1.
class MechanicTranslationalMassWithLever : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mL1 = 1.0, mL2 = 1.0;
    double mW = 2.0;
    double *mpM = nullptr, *mpB = nullptr;
    double *mpP1_f = nullptr, *mpP1_x = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr, *mpP1_me = nullptr;
    double *mpP2_f = nullptr, *mpP2_x = nullptr, *mpP2_v = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr, *mpP2_me = nullptr;
    DoubleIntegratorWithDamping mIntegrator;
};

} // namespace tlmhub
