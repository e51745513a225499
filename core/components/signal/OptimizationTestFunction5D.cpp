#include "core/ComponentFactory.h"
#include "core/components/signal/OptimizationTestFunctionND.h"

namespace tlmhub {

using OptimizationTestFunction5D = OptimizationTestFunctionND<5>;

TLMHUB_REGISTER_COMPONENT(OptimizationTestFunction5D, "Signal")

} // namespace tlmhub
