#pragma once
#include "core/Component.h"
#include "core/numerics/LookupTable.h"

#include <string>

namespace tlmhub {

// C-type engine: the throttle `in` (0..1) asks for the power in * P_max, delivered as the
// torque in * P_max / speed, capped by the full-load torque curve read from a CSV file
// (speed in column 0, maximum torque in column 1). The shaft sees it with zero impedance.
class CombustionEngine : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    bool loadCurve();

    Port* mpIn = nullptr;
    Port* mpP1 = nullptr;
    double* mpThrottle = nullptr;
    double* mpP1_w = nullptr;
    double* mpP1_c = nullptr;
    double* mpP1_Zc = nullptr;
    double mPMax = 150000.0;
    std::string mCharacteristics;
    LookupTable1D mMaxTorque;
};

} // namespace tlmhub
