// FMIWrapperQ: an imported FMI 2.0 co-simulation FMU whose power ports are of kind C (the
// FMU takes the wave variable and impedance and gives effort and flow), so this side is
// Q-type (fmu/FmuWrapper.h). FMUs with kind Q power ports go into FMIWrapper.
#include "core/ComponentFactory.h"
#include "fmu/FmuWrapper.h"

namespace tlmhub::fmu {

class FMIWrapperQ : public FmuWrapper {
public:
    FMIWrapperQ() : FmuWrapper(CqsKind::Q, 'C', "FMIWrapper") {}
};

TLMHUB_REGISTER_COMPONENT(FMIWrapperQ, "Connectivity")

} // namespace tlmhub::fmu
