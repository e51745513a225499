#pragma once
#include "core/Component.h"

namespace tlmhub {

// GUI numeric entry field. Registered C-type; the output is its start value
// (or what the GUI writes).
class SignalNumericalInput : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpOut = nullptr;
};

} // namespace tlmhub
