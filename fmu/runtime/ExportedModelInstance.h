#pragma once
// One instance of an exported model inside the FMU runtime: the FMI 2.0 co-simulation state
// machine (instantiated -> initialisation mode -> stepping -> terminated) over a Simulation.
// The C functions in Fmi2Functions.cpp check their arguments and call these members.
#include "core/Model.h"
#include "core/Simulation.h"
#include "fmu/Fmi2.h"
#include "fmu/ModelInterface.h"

#include <optional>
#include <string>
#include <vector>

namespace tlmhub::fmu {

class ExportedModelInstance {
public:
    enum class State { Instantiated, InitializationMode, Stepping, StepFailed, Terminated };

    // Null, with the reason logged, when the resources hold no model of this GUID.
    static ExportedModelInstance* create(const std::string& instanceName, const std::string& guid,
                               const std::string& resourceLocation, const fmi2CallbackFunctions* callbacks,
                               bool loggingOn);

    void setDebugLogging(bool on) { mDebugLogging = on; }
    fmi2Status setupExperiment(double startTime, std::optional<double> stopTime);
    fmi2Status enterInitializationMode();
    fmi2Status exitInitializationMode();
    fmi2Status terminate();
    fmi2Status reset();
    fmi2Status getReal(const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]);
    fmi2Status setReal(const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]);
    fmi2Status doStep(double currentCommunicationPoint, double communicationStepSize);
    fmi2Status doStepStatus() const { return mLastStepStatus; }
    double lastSuccessfulTime() const { return mTime; }
    // fmi2Terminated: after a discarded step the model cannot go on.
    bool terminated() const { return mState == State::StepFailed || mState == State::Terminated; }

    // fmi2Error with the message logged (category logStatusError).
    fmi2Status error(const std::string& message);
    void info(const std::string& message);

private:
    ExportedModelInstance(std::string instanceName, const fmi2CallbackFunctions& callbacks, bool loggingOn);
    void log(fmi2Status status, const char* category, const std::string& message);
    Result<ModelInterface> loadModel(const std::string& resourceDirectory, const std::string& guid);
    void restoreStarts();
    void writeInputs();

    std::string mName;
    fmi2CallbackFunctions mCallbacks;
    bool mDebugLogging = false;
    State mState = State::Instantiated;

    Model mModel;                 // as loaded; each initialisation compiles a copy
    ModelInterface mInterface;
    std::vector<double> mValues;  // inputs and parameters as set; outputs unused
    double mStartTime = 0.0;
    std::optional<double> mStopTime;
    std::optional<Simulation> mSimulation;   // from exitInitializationMode on
    std::vector<double*> mSlots;             // each NodeSlot variable's node value (else null)
    double mTime = 0.0;
    fmi2Status mLastStepStatus = fmi2OK;
};

} // namespace tlmhub::fmu
