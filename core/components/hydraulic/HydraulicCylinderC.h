#pragma once
#include "core/Component.h"
#include "core/components/hydraulic/HydraulicSubPortData.h"

#include <vector>

namespace tlmhub {

// C-type double-acting cylinder: two chamber volumes (multiport volumes with a
// piston and a leakage port each), viscous friction and optional end stops.
// HydraulicSymmetricCylinderC derives from it and only replaces the area inputs.
class HydraulicCylinderC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

protected:
    // Registers the area input variables and binds mpA1/mpA2.
    virtual void addAreaInputs();

    double* mpA1 = nullptr;
    double* mpA2 = nullptr;

private:
    void limitStroke(double& CxLim, double& ZxLim, double x3, double v3, double me, double sl) const;

    static constexpr double mWfak = 0.1;
    static constexpr double mAlpha = 0.1;
    bool mUseEndStops = true;

    // Internal piston (ci) and leakage (cl) wave variables of both chambers.
    double ci1 = 0.0, cl1 = 0.0, ci2 = 0.0, cl2 = 0.0;

    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double *mpSl = nullptr, *mpV01 = nullptr, *mpV02 = nullptr, *mpBp = nullptr;
    double *mpBetae = nullptr, *mpCLeak = nullptr, *mpQLeak = nullptr;
    std::size_t mNumPorts1 = 0, mNumPorts2 = 0;
    std::vector<HydraulicSubPortData> mP1, mP2;
    double *mpP3_x = nullptr, *mpP3_v = nullptr, *mpP3_c = nullptr, *mpP3_Zx = nullptr;
    double* mpP3_me = nullptr;
};

} // namespace tlmhub
