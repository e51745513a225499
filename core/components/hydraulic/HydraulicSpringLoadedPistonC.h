#pragma once
#include "core/Component.h"
#include "core/components/hydraulic/HydraulicSubPortData.h"

#include <vector>

namespace tlmhub {

// C-type cylinder with a constant spring (pre-load) force; like
// HydraulicCylinderC but with non-negative wave variables and no cavitation flags.
class HydraulicSpringLoadedPistonC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void limitStroke(double& CxLim, double& ZxLim, double x3, double v3, double me, double sl) const;

    static constexpr double mWfak = 0.1;
    static constexpr double mAlpha = 0.1;
    bool mUseEndStops = true;
    double ci1 = 0.0, cl1 = 0.0, ci2 = 0.0, cl2 = 0.0;

    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double *mpA1 = nullptr, *mpA2 = nullptr, *mpSl = nullptr, *mpFs = nullptr;
    double *mpV01 = nullptr, *mpV02 = nullptr, *mpBp = nullptr, *mpBetae = nullptr, *mpCLeak = nullptr;
    std::size_t mNumPorts1 = 0, mNumPorts2 = 0;
    std::vector<HydraulicSubPortData> mP1, mP2;
    double *mpP3_x = nullptr, *mpP3_v = nullptr, *mpP3_c = nullptr, *mpP3_Zx = nullptr;
    double* mpP3_me = nullptr;
};

} // namespace tlmhub
