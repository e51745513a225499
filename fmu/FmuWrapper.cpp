#include "fmu/FmuWrapper.h"

#include "core/System.h"
#include "fmu/FmuLoadPolicy.h"

#include <algorithm>
#include <map>

namespace tlmhub::fmu {

FmuWrapper::FmuWrapper(CqsKind kind, char powerPortKind, const char* otherType)
    : Component(kind), mPowerPortKind(powerPortKind), mOtherType(otherType)
{
}

FmuWrapper::~FmuWrapper() = default;

void FmuWrapper::configure()
{
    addConstant("path", "The FMU file (.fmu, FMI 2.0 co-simulation)", "", mPath, ParameterType::FilePath);
}

std::set<std::string> FmuWrapper::powerPortVariables(const ModelDescription& description)
{
    std::set<std::string> names;
    for (const PowerPort& port : description.powerPorts)
        for (const auto* slots : {&port.inputs, &port.outputs})
            for (const auto& [slot, variable] : *slots) names.insert(variable);
    return names;
}

Status FmuWrapper::checkDefinition(const ModelDescription& description) const
{
    for (const PowerPort& port : description.powerPorts)
        if (port.kind != mPowerPortKind)
            return {StatusCode::InvalidModel, "the FMU's power port '" + port.name + "' is of kind " + port.kind +
                                                  "; use " + mOtherType + " for this FMU"};
    // Every port and parameter name once (names become legal port names, which may clash).
    std::set<std::string> names{"path"};
    const auto claim = [&](const std::string& original) -> Status {
        const std::string name = sanitizeName(original);
        if (!names.insert(name).second)
            return {StatusCode::InvalidModel, "FMU variable '" + original + "' gives the name '" + name +
                                                  "', which another one has already"};
        return Status::ok();
    };
    const std::set<std::string> inPowerPorts = powerPortVariables(description);
    for (const PowerPort& port : description.powerPorts)
        if (Status claimed = claim(port.name); !claimed) return claimed;
    for (const ScalarVariable& v : description.variables) {
        const bool declared = v.causality == Causality::Input || v.causality == Causality::Output ||
                              v.causality == Causality::Parameter;
        if (v.type != VariableType::Real || !declared || inPowerPorts.count(v.name)) continue;
        if (Status claimed = claim(v.name); !claimed) return claimed;
    }
    return Status::ok();
}

Status FmuWrapper::loadExternalDefinition()
{
    const Parameter* path = parameters().find("path");
    const std::string requested = path ? path->value : std::string();
    // Ports, once declared, have connections and bound variables: a component keeps its FMU.
    if (mPackage) {
        if (requested == mLoadedPath) return Status::ok();
        return {StatusCode::InvalidParameter, "this component already wraps '" + mLoadedPath +
                                                  "'; use a new component for another FMU", modelPath() + ".path"};
    }
    // A new component has no FMU yet (initialize() says so if it never gets one).
    if (requested.empty()) return Status::ok();
    Result<std::filesystem::path> file = resolveFmuPath(fmuLoadPolicy(), requested, modelDirectory());
    if (!file) return {file.status().code(), file.status().message(), modelPath() + ".path"};
    Result<std::shared_ptr<const FmuPackage>> package = FmuPackage::open(*file);
    if (!package) return {package.status().code(), package.status().message(), modelPath() + ".path"};
    if (Status checked = checkDefinition((*package)->description()); !checked)
        return {checked.code(), checked.message(), modelPath()};
    mPackage = std::move(*package);
    declarePorts(mPackage->description());
    mLoadedPath = requested;
    return Status::ok();
}

void FmuWrapper::declarePorts(const ModelDescription& description)
{
    std::map<std::string, fmi2ValueReference> references;
    for (const ScalarVariable& v : description.variables) references[v.name] = v.valueReference;
    const std::set<std::string> inPowerPorts = powerPortVariables(description);
    for (const PowerPort& powerPort : description.powerPorts) {
        NodeType type = NodeType::Empty;
        nodeTypeFromName(powerPort.nodeType, type);
        Port* port = addPowerPort(sanitizeName(powerPort.name), type);
        const auto slotOf = [&](const std::string& shortName) {
            const auto& variables = nodeTypeInfo(type).variables;
            for (std::size_t i = 0; i < variables.size(); ++i)
                if (variables[i].shortName == shortName) return static_cast<int>(i);
            return 0;   // the parser admits known slots only
        };
        for (const auto& [slot, variable] : powerPort.inputs)
            mInputs.push_back({port, slotOf(slot), references[variable], nullptr});
        for (const auto& [slot, variable] : powerPort.outputs)
            mOutputs.push_back({port, slotOf(slot), references[variable], nullptr});
        ++mPowerPortCount;
    }

    for (const ScalarVariable& v : description.variables) {
        if (v.type != VariableType::Real || inPowerPorts.count(v.name)) continue;
        const std::string name = sanitizeName(v.name);
        if (v.causality == Causality::Input) {
            double** data = &mAutoPointers.emplace_back(nullptr);
            Port* port = addInputVariable(name, v.description, v.unit, v.start.value_or(0.0), data);
            mInputs.push_back({port, 0, v.valueReference, data});
        } else if (v.causality == Causality::Output) {
            double** data = &mAutoPointers.emplace_back(nullptr);
            Port* port = addOutputVariable(name, v.description, v.unit, data);
            mOutputs.push_back({port, 0, v.valueReference, data});
        } else if (v.causality == Causality::Parameter) {
            double& value = mParameterValues.emplace_back(v.start.value_or(0.0));
            addConstant(name, v.description, v.unit, value, value);
            mParameterReferences.push_back(v.valueReference);
        }
    }
    for (const Binding& b : mInputs) mInputReferences.push_back(b.reference);
    for (const Binding& b : mOutputs) mOutputReferences.push_back(b.reference);
    mInputValues.resize(mInputs.size());
    mOutputValues.resize(mOutputs.size());
    mParameterBuffer.resize(mParameterReferences.size());
}

void FmuWrapper::logFromFmu(FmuInstance::LogLevel level, const std::string& text)
{
    switch (level) {
    case FmuInstance::LogLevel::Info: addInfoMessage(text); break;
    case FmuInstance::LogLevel::Warning: addWarningMessage(text); break;
    case FmuInstance::LogLevel::Error: addErrorMessage(text); break;
    }
}

void FmuWrapper::initialize()
{
    mInstance.reset();
    if (!mPackage) {
        stopSimulation("no FMU loaded (parameter path: '" + mPath + "')");
        return;
    }
    const auto bindSlots = [&](const std::vector<Binding>& bindings, std::vector<double*>& data) {
        data.clear();
        for (const Binding& b : bindings) data.push_back(b.autoData ? *b.autoData : getSafeNodeDataPtr(b.port, b.slot));
    };
    bindSlots(mInputs, mInputData);
    bindSlots(mOutputs, mOutputData);

    Result<std::unique_ptr<FmuInstance>> instance = FmuInstance::create(
        mPackage, name(), [this](FmuInstance::LogLevel level, const std::string& text) { logFromFmu(level, text); });
    if (!instance) {
        stopSimulation("FMU '" + mPath + "': " + instance.status().message());
        return;
    }
    mInstance = std::move(*instance);
    std::copy(mParameterValues.begin(), mParameterValues.end(), mParameterBuffer.begin());
    for (std::size_t i = 0; i < mInputs.size(); ++i) mInputValues[i] = *mInputData[i];
    Status status = mInstance->enterInitialization(mTime);
    if (status && !mInstance->setReal(mParameterReferences, mParameterBuffer.data()))
        status = {StatusCode::InitFailed, "fmi2SetReal of the parameters failed"};
    if (status && !mInstance->setReal(mInputReferences, mInputValues.data()))
        status = {StatusCode::InitFailed, "fmi2SetReal of the inputs failed"};
    if (status) status = mInstance->exitInitialization();
    if (status && !mInstance->getReal(mOutputReferences, mOutputValues.data()))
        status = {StatusCode::InitFailed, "fmi2GetReal of the outputs failed"};
    if (!status) {
        stopSimulation("FMU '" + mPath + "': " + status.message());
        return;
    }
    for (std::size_t i = 0; i < mOutputs.size(); ++i) *mOutputData[i] = mOutputValues[i];
}

void FmuWrapper::simulateOneTimestep()
{
    if (!mInstance) return;
    for (std::size_t i = 0; i < mInputData.size(); ++i) mInputValues[i] = *mInputData[i];
    // mTime has already advanced: the step runs from the previous communication point.
    if (!mInstance->setReal(mInputReferences, mInputValues.data()) || !mInstance->doStep(mTime - mTimestep, mTimestep) ||
        !mInstance->getReal(mOutputReferences, mOutputValues.data())) {
        stopSimulation("FMU '" + mPath + "' failed at t = " + std::to_string(mTime));
        mInstance.reset();
        return;
    }
    for (std::size_t i = 0; i < mOutputData.size(); ++i) *mOutputData[i] = mOutputValues[i];
}

void FmuWrapper::finalize()
{
    mInstance.reset();
}

} // namespace tlmhub::fmu
