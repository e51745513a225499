#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type inductance: a TLM line element with a numerical damping filter.
class ElectricInductanceC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPel1 = nullptr, *mpPel2 = nullptr;
    double *mpInduct = nullptr, *mpAlpha = nullptr, *mpCp = nullptr;
    // Wave states kept inside the component between steps.
    double mC1 = 0.0, mC2 = 0.0, mZc1 = 0.0, mZc2 = 0.0;
    double *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
    double *mpPel2_i = nullptr, *mpPel2_c = nullptr, *mpPel2_Zc = nullptr;
};

} // namespace tlmhub
