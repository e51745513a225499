#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type generated fuel tank: an ideal pressure source whose pressure is the ullage
// pressure plus the hydrostatic head of the remaining fuel; the fuel drawn through PT is
// integrated into the consumed mass. An empty tank gives zero pressure.
class HydraulicFuelTankG : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPT = nullptr;
    double *mpPT_q = nullptr, *mpPT_c = nullptr, *mpPT_Zc = nullptr;
    double *mp_gx = nullptr, *mp_rhofuel = nullptr, *mp_p0 = nullptr, *mp_hf = nullptr;
    double *mp_massfuel0 = nullptr, *mp_massfuelmax = nullptr;
    double *mp_massfuel = nullptr, *mp_consfuel = nullptr;

    // Parameters are read once at initialisation (generated-component convention).
    double rhofuel = 0, p0 = 0, hf = 0, massfuel0 = 0, massfuelmax = 0;
    double mConsfuel = 0.0, mPrevQ = 0.0;
};

} // namespace tlmhub
