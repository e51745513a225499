#pragma once
#include "core/Component.h"
#include "core/components/hydraulic/HydraulicSubPortData.h"

#include <vector>

namespace tlmhub {

// C-type lumped volume with any number of connections on one multiport; all
// connections share one pressure.
class HydraulicVolumeMultiPort : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpV = nullptr;
    double* mpBetae = nullptr;
    double* mpAlpha = nullptr;
    double mPhigh = 2e7;
    std::size_t mNumPorts = 0;
    std::vector<HydraulicSubPortData> mP1;
};

} // namespace tlmhub
