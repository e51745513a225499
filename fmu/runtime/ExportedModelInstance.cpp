#include "fmu/runtime/ExportedModelInstance.h"

#include "core/Node.h"
#include "core/Parameter.h"
#include "core/ParameterPath.h"
#include "core/Port.h"
#include "core/hmf/HmfLoader.h"
#include "fmu/Guid.h"
#include "fmu/runtime/ResourceLocation.h"

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

namespace tlmhub::fmu {
namespace {

// Without a stop time the simulation is compiled to run this long: far beyond any
// co-simulation (steps are counted in a size_t, and nothing is allocated per step).
constexpr double kOpenEndedHorizon = 1e9;

std::optional<std::string> readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The exported component parameters, one path per line (fmu/FmuExport.cpp writes them).
std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty())
            lines.push_back(line);
    return lines;
}

} // namespace

ExportedModelInstance::ExportedModelInstance(std::string instanceName, const fmi2CallbackFunctions& callbacks, bool loggingOn)
    : mName(std::move(instanceName)), mCallbacks(callbacks), mDebugLogging(loggingOn)
{
}

ExportedModelInstance* ExportedModelInstance::create(const std::string& instanceName, const std::string& guid,
                                 const std::string& resourceLocation, const fmi2CallbackFunctions* callbacks,
                                 bool loggingOn)
{
    auto instance = std::unique_ptr<ExportedModelInstance>(new ExportedModelInstance(instanceName, *callbacks, loggingOn));
    std::optional<std::string> directory = directoryOfFileUri(resourceLocation);
    if (!directory) {
        instance->error("fmi2Instantiate: the resource location '" + resourceLocation + "' is not a file:// URI");
        return nullptr;
    }
    Result<ModelInterface> loaded = instance->loadModel(*directory, guid);
    if (!loaded) {
        instance->error("fmi2Instantiate: " + describe(loaded.status()));
        return nullptr;
    }
    instance->mInterface = std::move(*loaded);
    instance->restoreStarts();
    instance->info("instantiated model '" + instance->mInterface.description.modelName + "'");
    return instance.release();
}

Result<ModelInterface> ExportedModelInstance::loadModel(const std::string& resourceDirectory, const std::string& guid)
{
    const std::string hmfPath = resourceDirectory + "/model.hmf";
    std::optional<std::string> hmf = readFile(hmfPath);
    if (!hmf)
        return Status{StatusCode::IoError, "cannot read " + hmfPath};
    const std::vector<std::string> parameters = linesOf(readFile(resourceDirectory + "/parameters.txt").value_or(""));
    if (guidOfModel(*hmf, parameters) != guid)
        return Status{StatusCode::InvalidModel, "GUID " + guid + " is not the GUID of the model in " + hmfPath};
    LoadedModel loaded = loadHmfString(*hmf, resourceDirectory, hmfPath);
    if (loaded.hasErrors())
        return loaded.status();
    mModel = Model(std::move(loaded.root));
    Result<ModelInterface> described = describeInterface(mModel.root(), {parameters, {}});
    if (!described)
        return described;
    if (Status started = takeInputStartsFromInitialisation(*described, mModel); !started)
        return started;
    return described;
}

void ExportedModelInstance::log(fmi2Status status, const char* category, const std::string& message)
{
    if (mCallbacks.logger)
        mCallbacks.logger(mCallbacks.componentEnvironment, mName.c_str(), status, category, "%s", message.c_str());
}

fmi2Status ExportedModelInstance::error(const std::string& message)
{
    log(fmi2Error, "logStatusError", message);
    return fmi2Error;
}

void ExportedModelInstance::info(const std::string& message)
{
    if (mDebugLogging)
        log(fmi2OK, "logAll", message);
}

void ExportedModelInstance::restoreStarts()
{
    const auto& variables = mInterface.description.variables;
    mValues.assign(variables.size(), 0.0);
    for (std::size_t i = 0; i < variables.size(); ++i)
        mValues[i] = variables[i].start.value_or(0.0);
    mSimulation.reset();
    mSlots.assign(variables.size(), nullptr);
    mTime = mStartTime;
    mLastStepStatus = fmi2OK;
}

fmi2Status ExportedModelInstance::setupExperiment(double startTime, std::optional<double> stopTime)
{
    if (mState != State::Instantiated)
        return error("fmi2SetupExperiment: only allowed after fmi2Instantiate or fmi2Reset");
    if (!std::isfinite(startTime) || (stopTime && !(*stopTime >= startTime)))
        return error("fmi2SetupExperiment: need a finite start time and a stop time not before it");
    mStartTime = startTime;
    mStopTime = stopTime;
    mTime = startTime;
    return fmi2OK;
}

fmi2Status ExportedModelInstance::enterInitializationMode()
{
    if (mState != State::Instantiated)
        return error("fmi2EnterInitializationMode: only allowed after fmi2Instantiate or fmi2SetupExperiment");
    mState = State::InitializationMode;
    return fmi2OK;
}

// Compiles a copy of the model with the parameters as set, initialises it at the start
// time and writes the inputs into their nodes: from here on outputs are the model's.
fmi2Status ExportedModelInstance::exitInitializationMode()
{
    if (mState != State::InitializationMode)
        return error("fmi2ExitInitializationMode: not in initialisation mode");
    Result<Model> model = mModel.copy();
    if (!model)
        return error("fmi2ExitInitializationMode: " + describe(model.status()));
    const auto& variables = mInterface.description.variables;
    double timestep = 0.0;
    for (std::size_t i = 0; i < variables.size(); ++i)
        if (mInterface.bindings[i].kind == VariableBinding::Kind::Timestep)
            timestep = mValues[i];
    // System parameters first: component values may refer to them.
    for (bool systemParameters : {true, false}) {
        for (std::size_t i = 0; i < variables.size(); ++i) {
            const VariableBinding& binding = mInterface.bindings[i];
            if (binding.kind != VariableBinding::Kind::Parameter ||
                (binding.parameterPath.find('.') == std::string::npos) != systemParameters)
                continue;
            if (Status set = setParameterValue(model->root(), binding.parameterPath, formatNumber(mValues[i])); !set)
                return error("fmi2ExitInitializationMode: " + describe(set));
        }
    }
    // A signal input's value as set is its node's start value, so components initialise
    // with it as with a constant source. (A power port's node is shared with the component
    // on the other side, whose start values stay; writeInputs() sets its inputs for the steps.)
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableBinding& binding = mInterface.bindings[i];
        if (variables[i].causality != Causality::Input || binding.kind != VariableBinding::Kind::NodeSlot)
            continue;
        Port* port = model->root().component(binding.component)->port(binding.port);
        if (port->kind() != PortKind::Write)
            continue;
        if (!port->hasStartNode())
            port->createStartNode();
        port->startValues[binding.slot] = mValues[i];
    }
    SimulationSettings settings{mStartTime, mStopTime.value_or(mStartTime + kOpenEndedHorizon), timestep, 0};
    Result<Simulation> compiled = compile(std::move(*model), settings);
    if (!compiled)
        return error("fmi2ExitInitializationMode: " + describe(compiled.status()));
    mSimulation.emplace(std::move(*compiled));
    if (Status started = mSimulation->initialise(); !started)
        return error("fmi2ExitInitializationMode: " + describe(started));
    // Node data has its final place once initialised.
    System& root = mSimulation->system();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableBinding& binding = mInterface.bindings[i];
        if (binding.kind == VariableBinding::Kind::NodeSlot)
            mSlots[i] = root.component(binding.component)->port(binding.port)->node()->data() + binding.slot;
    }
    writeInputs();
    mTime = mStartTime;
    mState = State::Stepping;
    info("initialised at t=" + formatNumber(mStartTime) + " with time step " + formatNumber(timestep));
    return fmi2OK;
}

void ExportedModelInstance::writeInputs()
{
    const auto& variables = mInterface.description.variables;
    for (std::size_t i = 0; i < variables.size(); ++i)
        if (variables[i].causality == Causality::Input && mSlots[i])
            *mSlots[i] = mValues[i];
}

fmi2Status ExportedModelInstance::terminate()
{
    if (mState != State::Stepping && mState != State::StepFailed)
        return error("fmi2Terminate: the model was not initialised");
    mState = State::Terminated;
    return fmi2OK;
}

fmi2Status ExportedModelInstance::reset()
{
    mState = State::Instantiated;
    mStopTime.reset();
    mStartTime = 0.0;
    restoreStarts();
    return fmi2OK;
}

fmi2Status ExportedModelInstance::getReal(const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    for (size_t k = 0; k < nvr; ++k) {
        if (vr[k] >= mValues.size())
            return error("fmi2GetReal: no variable has value reference " + std::to_string(vr[k]));
        const ScalarVariable& variable = mInterface.description.variables[vr[k]];
        if (variable.causality != Causality::Output) {
            value[k] = mValues[vr[k]];
            continue;
        }
        // The model is compiled with its parameters at the end of initialisation mode.
        if (!mSlots[vr[k]])
            return error("fmi2GetReal: output '" + variable.name + "' is known from fmi2ExitInitializationMode on");
        value[k] = *mSlots[vr[k]];
    }
    return fmi2OK;
}

fmi2Status ExportedModelInstance::setReal(const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[])
{
    for (size_t k = 0; k < nvr; ++k) {
        if (vr[k] >= mValues.size())
            return error("fmi2SetReal: no variable has value reference " + std::to_string(vr[k]));
        const ScalarVariable& variable = mInterface.description.variables[vr[k]];
        if (variable.causality == Causality::Output)
            return error("fmi2SetReal: '" + variable.name + "' is an output");
        if (variable.causality == Causality::Parameter && mState != State::Instantiated &&
            mState != State::InitializationMode)
            return error("fmi2SetReal: parameter '" + variable.name +
                         "' is fixed: set it before fmi2ExitInitializationMode");
        if (variable.causality == Causality::Parameter && !(std::isfinite(value[k]) &&
                                                            (variable.name != "tlmhub.timestep" || value[k] > 0.0)))
            return error("fmi2SetReal: " + formatNumber(value[k]) + " is no value for '" + variable.name + "'");
        mValues[vr[k]] = value[k];
    }
    return fmi2OK;
}

// One communication step: the inputs as set apply from its start; the step must be a whole
// number of model steps, so communication points land on the model's own steps.
fmi2Status ExportedModelInstance::doStep(double currentCommunicationPoint, double communicationStepSize)
{
    if (mState != State::Stepping)
        return error("fmi2DoStep: the model is not initialised, or a step failed or it was terminated");
    const double dt = mSimulation->timestep();
    const double tolerance = 1e-9 * std::max(std::abs(mTime), dt);
    if (std::abs(currentCommunicationPoint - mTime) > tolerance)
        return error("fmi2DoStep: the communication point " + formatNumber(currentCommunicationPoint) +
                     " is not the FMU's time " + formatNumber(mTime));
    const double steps = std::round(communicationStepSize / dt);
    if (!(steps >= 1.0) || std::abs(steps * dt - communicationStepSize) > 1e-9 * communicationStepSize)
        return error("fmi2DoStep: the communication step " + formatNumber(communicationStepSize) +
                     " is not a whole number of model steps of " + formatNumber(dt));
    const double target = mTime + communicationStepSize;
    if (target > mSimulation->stopTime() + tolerance)
        return error("fmi2DoStep: the step ends at " + formatNumber(target) + ", after the stop time " +
                     formatNumber(mSimulation->stopTime()));
    writeInputs();
    const std::size_t before = mSimulation->takenSteps();
    Status ran = mSimulation->runSteps(static_cast<std::size_t>(steps));
    mTime = mSimulation->time();
    if (!ran) {
        // A model that stops itself (a stop component, a failing component) ends the
        // co-simulation at the last step it took: discard, as the standard has it.
        mState = State::StepFailed;
        mLastStepStatus = fmi2Discard;
        log(fmi2Discard, "logStatusDiscard", "fmi2DoStep: " + describe(ran));
        return fmi2Discard;
    }
    if (mSimulation->takenSteps() - before != static_cast<std::size_t>(steps))
        return error("fmi2DoStep: the model took " + std::to_string(mSimulation->takenSteps() - before) +
                     " steps instead of " + formatNumber(steps));
    mLastStepStatus = fmi2OK;
    return fmi2OK;
}

} // namespace tlmhub::fmu
