#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Q-type rack (P1, translational) and pinion (P2, rotational) with inertia and
// viscous friction. Starts from rest at zero angle regardless of start values.
class MechanicRackAndPinion : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double mK = 0.0;
    double *mpOmega = nullptr, *mpJ = nullptr, *mpB = nullptr;
    double *mpP1_f = nullptr, *mpP1_x = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr, *mpP1_me = nullptr;
    double *mpP2_T = nullptr, *mpP2_a = nullptr, *mpP2_w = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr;
    double mNum[3] = {0.0, 1.0, 0.0};
    double mDen[3] = {0.0, 0.0, 0.0};
    SecondOrderTransferFunction mFilter;
    Integrator mIntegrator;
};

} // namespace tlmhub
