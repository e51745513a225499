#include "core/ComponentFactory.h"
#include "core/components/signal/OptimizationTestFunctionND.h"

namespace tlmhub {

using OptimizationTestFunction6D = OptimizationTestFunctionND<6>;

TLMHUB_REGISTER_COMPONENT(OptimizationTestFunction6D, "Signal")

} // namespace tlmhub
