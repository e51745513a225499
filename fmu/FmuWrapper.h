#pragma once
// What FMIWrapper and FMIWrapperQ share: a component that runs an imported FMI 2.0
// co-simulation FMU (parameter `path`, the .fmu file). Its ports and parameters come from
// the FMU, declared in loadExternalDefinition once `path` is known:
//  - each real input not in a power port: an input variable (signal read port, with a
//    `<name>#Value` default), each real output likewise an output variable; names made
//    legal port names;
//  - each power port of tlmhub's annotation: a power port of its node type; the FMU's inputs
//    are read from the node's slots, its outputs written to them;
//  - each real parameter: a component parameter (the FMU's start as default), set before
//    the FMU initialises.
// Every step sets the inputs, advances the FMU by one model step and reads the outputs.
#include "core/Component.h"
#include "fmu/FmuInstance.h"
#include "fmu/FmuPackage.h"

#include <deque>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace tlmhub::fmu {

class FmuWrapper : public Component {
public:
    // `powerPortKind`: the kind of FMU power port this type plays against ('Q': the wrapper
    // is C-type; 'C': Q-type), `otherType` the type name that takes the other kind.
    FmuWrapper(CqsKind kind, char powerPortKind, const char* otherType);
    ~FmuWrapper() override;

    void configure() override;
    Status loadExternalDefinition() override;
    bool loadsExternalDefinition() const override { return true; }
    void initialize() override;
    void simulateOneTimestep() override;
    void finalize() override;

protected:
    bool hasPowerPorts() const { return mPowerPortCount != 0; }

private:
    // One FMU variable reached through a node slot (signal or power port).
    struct Binding {
        Port* port = nullptr;
        int slot = 0;
        fmi2ValueReference reference = 0;
        double** autoData = nullptr;   // input/output variables: bound by the core
    };

    static std::set<std::string> powerPortVariables(const ModelDescription& description);
    // Refuses an FMU this type cannot wrap, before anything is declared.
    Status checkDefinition(const ModelDescription& description) const;
    void declarePorts(const ModelDescription& description);
    void logFromFmu(FmuInstance::LogLevel level, const std::string& text);

    char mPowerPortKind;
    const char* mOtherType;
    std::string mPath;
    std::string mLoadedPath;
    std::size_t mPowerPortCount = 0;
    std::shared_ptr<const FmuPackage> mPackage;
    std::unique_ptr<FmuInstance> mInstance;

    std::deque<double*> mAutoPointers;   // stable addresses for the core's variable binding
    std::deque<double> mParameterValues; // stable addresses for parameter evaluation

    std::vector<Binding> mInputs, mOutputs;
    std::vector<fmi2ValueReference> mInputReferences, mOutputReferences, mParameterReferences;
    std::vector<double*> mInputData, mOutputData;   // node slots, bound in initialize()
    std::vector<double> mInputValues, mOutputValues, mParameterBuffer;
};

} // namespace tlmhub::fmu
