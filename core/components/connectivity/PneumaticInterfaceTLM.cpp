#include "core/ComponentFactory.h"
#include "core/components/connectivity/TlmInterface.h"

namespace tlmhub {

struct PneumaticInterfaceTLMSpec {
    static constexpr NodeType node = NodeType::Pneumatic;
    static constexpr int waveSlot = NodePneumatic::WaveVariable;
    static constexpr int impedanceSlot = NodePneumatic::CharImpedance;
    static constexpr const char* flowName = "e2";
    static constexpr const char* flowDescription = "Received (delayed) energy flow";
    static constexpr const char* flowUnit = "J/s";
    static constexpr const char* effortName = "p2";
    static constexpr const char* effortDescription = "Received (delayed) pressure";
    static constexpr const char* effortUnit = "Pa";
    static constexpr const char* impedanceUnit = "Pa s/J";
};

using PneumaticInterfaceTLM = TlmInterface<PneumaticInterfaceTLMSpec>;

TLMHUB_REGISTER_COMPONENT(PneumaticInterfaceTLM, "Connectivity")

} // namespace tlmhub
