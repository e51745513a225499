#pragma once
#include "core/Component.h"

namespace tlmhub {

// GUI on/off switch (also the "momentary switch" subtype); the GUI writes out,
// so in batch runs it stays 0.
class SignalAnimationSwitch : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpOut = nullptr;
};

} // namespace tlmhub
