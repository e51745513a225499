#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// C-type digital-hydraulics piston: four chambers on one rod (1 and 3 push one
// way, 2 and 4 the other), six leakage paths, optional end stops.
class HydraulicFourChamberPiston : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void limitStroke(double x5, double v5, double me, double sl);

    static constexpr double mWfak = 0.1;
    static constexpr double mAlpha = 0.1;
    bool mUseEndStops = true;

    // Per chamber (index 0..3 = chamber 1..4): piston and leakage wave variables.
    double mCi[4] = {0.0, 0.0, 0.0, 0.0};
    double mCl[4] = {0.0, 0.0, 0.0, 0.0};
    // End-stop state kept between steps.
    double mCxLim = 0.0;
    double mZxLim = 0.0;

    Port* mpP[4] = {nullptr, nullptr, nullptr, nullptr};
    Port* mpP5 = nullptr;
    double* mpA[4] = {nullptr, nullptr, nullptr, nullptr};
    double* mpV0[4] = {nullptr, nullptr, nullptr, nullptr};
    double *mpSl = nullptr, *mpBp = nullptr, *mpBetae = nullptr;
    double *mpCLeak12 = nullptr, *mpCLeak13 = nullptr, *mpCLeak14 = nullptr;
    double *mpCLeak23 = nullptr, *mpCLeak24 = nullptr, *mpCLeak34 = nullptr;

    std::size_t mNumPorts[4] = {0, 0, 0, 0};
    std::vector<double*> mvp_p[4], mvp_q[4], mvp_c[4], mvp_Zc[4];
    double *mpP5_x = nullptr, *mpP5_v = nullptr, *mpP5_c = nullptr, *mpP5_Zx = nullptr;
    double* mpP5_me = nullptr;
};

} // namespace tlmhub
