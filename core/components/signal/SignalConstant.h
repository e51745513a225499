#pragma once
#include "core/Component.h"

namespace tlmhub {

// Constant source: the output's start value y#Value is the constant; nothing is computed.
class SignalConstant : public ComponentSignal {
public:
    void configure() override;

private:
    double* mpY = nullptr;
};

} // namespace tlmhub
