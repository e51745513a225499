#pragma once
#include "core/Component.h"

namespace tlmhub {

// An output of the model to another program (an exported FMU's real output): the program
// reads the input's node between steps; the component computes nothing.
class SignalOutputInterface : public ComponentSignal {
public:
    void configure() override;

private:
    double* mpIn = nullptr;
};

} // namespace tlmhub
