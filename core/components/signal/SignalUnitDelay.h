#pragma once
#include "core/Component.h"

namespace tlmhub {

// Passes the input through. The input is not a sort dependency, so inside a loop
// the block runs before its source and therefore outputs last step's value.
class SignalUnitDelay : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
