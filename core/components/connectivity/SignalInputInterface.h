#pragma once
#include "core/Component.h"

namespace tlmhub {

// An input of the model from another program (an exported FMU's real input): the program
// writes the output's node between steps; the component computes nothing.
class SignalInputInterface : public ComponentSignal {
public:
    void configure() override;

private:
    double* mpOut = nullptr;
};

} // namespace tlmhub
