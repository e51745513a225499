#pragma once
// The outcome of an operation on a model: a stable code from one catalogue, a message for
// people, and the model path it concerns ("Sub$Comp" or "Sub$Comp.param"; empty for the
// whole model). Result<T> is a value or such a failure.
#include <optional>
#include <string>
#include <utility>

namespace tlmhub {

// Stable codes: the names (statusCodeName) are part of the CLI's and the server's output.
enum class StatusCode {
    Ok,
    UnknownComponentType,   // a component type that no library registers
    IllegalConnection,      // ports that may not be connected
    UnconnectedPort,        // a required port or system port left open
    UndefinedKind,          // a subsystem whose C/Q/S kind cannot be determined
    InvalidParameter,       // a parameter value that does not evaluate
    UnknownParameter,       // setParameter of a path that names no parameter
    InvalidSettings,        // times, step or sample count out of range
    AlgebraicLoop,          // signal components that depend on each other in one step
    InitFailed,             // a component refused to initialise
    SimulationStopped,      // a component or the caller stopped the run before its end
    SimulationEnded,        // a component ended the run as the model designs it (SignalStopSimulation)
    InvalidState,           // an operation the simulation's state does not allow
    NotFound,               // a component, port, system port, parameter or variable name that names nothing
    IllegalGrouping,        // components that cannot be grouped into a subsystem, or ungrouped
    IoError,                // a file that cannot be read, written or loaded
    InvalidModel,           // model text that is not a model, or breaks a load limit
    RestartRequired,        // a change while running to a parameter only a new start applies
};

const char* statusCodeName(StatusCode code);

class Status {
public:
    Status() = default;
    Status(StatusCode code, std::string message, std::string path = {})
        : mCode(code), mMessage(std::move(message)), mPath(std::move(path))
    {
    }
    static Status ok() { return {}; }

    bool isOk() const { return mCode == StatusCode::Ok; }
    explicit operator bool() const { return isOk(); }
    StatusCode code() const { return mCode; }
    const char* codeName() const { return statusCodeName(mCode); }
    const std::string& message() const { return mMessage; }
    const std::string& path() const { return mPath; }

private:
    StatusCode mCode = StatusCode::Ok;
    std::string mMessage;
    std::string mPath;
};

template <typename T>
class Result {
public:
    Result(T value) : mValue(std::move(value)) {}
    Result(Status failure) : mStatus(std::move(failure)) {}

    bool isOk() const { return mValue.has_value(); }
    explicit operator bool() const { return isOk(); }
    const Status& status() const { return mStatus; }
    T& value() { return *mValue; }
    const T& value() const { return *mValue; }
    T* operator->() { return &*mValue; }
    const T* operator->() const { return &*mValue; }
    T& operator*() { return *mValue; }
    const T& operator*() const { return *mValue; }

private:
    std::optional<T> mValue;
    Status mStatus;
};

// The one text of a failure for people (CLI lines, validation reports, logs):
// "code: message", and " (at path)" when it concerns a part of the model.
std::string describe(const Status& status);

} // namespace tlmhub
