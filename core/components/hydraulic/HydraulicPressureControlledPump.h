#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type pressure-compensated (load-sensing) variable pump: a regulator sets the
// displacement so that p2 stays p_dif above the pressure at PREF. The regulator is
// a rate- and amplitude-limited discrete second-order filter.
class HydraulicPressureControlledPump : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double fltppu(double u, double w01, double g1, double g2, double ymin, double ymax, double vmin,
                  double vmax);

    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpPREF = nullptr;
    double *mpEps = nullptr, *mpA = nullptr;
    double *mpPdif = nullptr, *mpOmegap = nullptr, *mpQmax = nullptr, *mpLp = nullptr, *mpRp = nullptr;
    double *mpOmegap1 = nullptr, *mpClp = nullptr, *mpTaov = nullptr, *mpTp = nullptr, *mpTm = nullptr;
    double mQmin = 0.0;
    const double mPnom = 7e6, mMovementNom = 125.0;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_p = nullptr, *mpP3_q = nullptr, *mpP3_c = nullptr;

    // Regulator filter state.
    double mY1 = 0.0, mY2 = 0.0, mU1 = 0.0, mU2 = 0.0, mYd = 0.0, mUd = 0.0, mVd = 0.0;
};

} // namespace tlmhub
