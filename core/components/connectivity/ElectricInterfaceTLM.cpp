#include "core/ComponentFactory.h"
#include "core/components/connectivity/TlmInterface.h"

namespace tlmhub {

struct ElectricInterfaceTLMSpec {
    static constexpr NodeType node = NodeType::Electric;
    static constexpr int waveSlot = NodeElectric::WaveVariable;
    static constexpr int impedanceSlot = NodeElectric::CharImpedance;
    static constexpr const char* flowName = "i2";
    static constexpr const char* flowDescription = "Received (delayed) current";
    static constexpr const char* flowUnit = "A";
    static constexpr const char* effortName = "u2";
    static constexpr const char* effortDescription = "Received (delayed) voltage";
    static constexpr const char* effortUnit = "V";
    static constexpr const char* impedanceUnit = "V/A";
};

using ElectricInterfaceTLM = TlmInterface<ElectricInterfaceTLMSpec>;

TLMHUB_REGISTER_COMPONENT(ElectricInterfaceTLM, "Connectivity")

} // namespace tlmhub
