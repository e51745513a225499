#pragma once
#include "core/Component.h"

#include <string>

namespace tlmhub {

// GUI numeric display. Registered C-type like the reference; computes nothing.
class SignalDisplay : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    std::string mDescription;
    std::string mUnit;
    double mUnitscaling = 1.0;
    int mPrecision = 8;
    std::string mBackgroundcolor;
    std::string mTextcolor;
};

} // namespace tlmhub
