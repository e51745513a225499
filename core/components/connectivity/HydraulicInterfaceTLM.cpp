#include "core/ComponentFactory.h"
#include "core/components/connectivity/TlmInterface.h"

namespace tlmhub {

struct HydraulicInterfaceTLMSpec {
    static constexpr NodeType node = NodeType::Hydraulic;
    static constexpr int waveSlot = NodeHydraulic::WaveVariable;
    static constexpr int impedanceSlot = NodeHydraulic::CharImpedance;
    static constexpr const char* flowName = "q2";
    static constexpr const char* flowDescription = "Received (delayed) flow";
    static constexpr const char* flowUnit = "m^3/s";
    static constexpr const char* effortName = "p2";
    static constexpr const char* effortDescription = "Received (delayed) pressure";
    static constexpr const char* effortUnit = "Pa";
    static constexpr const char* impedanceUnit = "Pa s/m^3";
};

using HydraulicInterfaceTLM = TlmInterface<HydraulicInterfaceTLMSpec>;

TLMHUB_REGISTER_COMPONENT(HydraulicInterfaceTLM, "Connectivity")

} // namespace tlmhub
