#pragma once
// One running instance of an FMU's co-simulation code: the shared library opened from the
// unpacked package, all FMI 2.0 co-simulation functions looked up, and one fmi2Component
// through its life (instantiate, experiment set-up, initialisation, steps, terminate, free).
// The FMU's log messages reach the logger given at load.
#include "core/Status.h"
#include "fmu/Fmi2.h"
#include "fmu/FmuPackage.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tlmhub::fmu {

class FmuInstance {
public:
    enum class LogLevel { Info, Warning, Error };
    using Logger = std::function<void(LogLevel, const std::string&)>;

    // Opens the library, looks up every function and instantiates the FMU. IoError when the
    // library is missing or does not load, InvalidModel for a missing function, InitFailed
    // when fmi2Instantiate refuses.
    static Result<std::unique_ptr<FmuInstance>> create(std::shared_ptr<const FmuPackage> package,
                                                       const std::string& instanceName, Logger logger);
    ~FmuInstance();   // terminates an initialised instance, frees it, closes the library
    FmuInstance(const FmuInstance&) = delete;
    FmuInstance& operator=(const FmuInstance&) = delete;

    // setupExperiment from `startTime` (no stop time) and enterInitializationMode.
    Status enterInitialization(double startTime);
    Status exitInitialization();

    // The step functions report failure as false (the caller stops the run); no allocation.
    bool setReal(const std::vector<fmi2ValueReference>& references, const double* values) noexcept;
    bool getReal(const std::vector<fmi2ValueReference>& references, double* values) noexcept;
    bool doStep(double currentTime, double stepSize) noexcept;

private:
    struct Functions {
#define TLMHUB_FMI2_POINTER(name) name##TYPE* name = nullptr;
        TLMHUB_FMI2_COSIMULATION_FUNCTIONS(TLMHUB_FMI2_POINTER)
#undef TLMHUB_FMI2_POINTER
    };

    FmuInstance(std::shared_ptr<const FmuPackage> package, Logger logger)
        : mPackage(std::move(package)), mLogger(std::move(logger))
    {
    }
    static void logFromFmu(fmi2ComponentEnvironment environment, fmi2String instanceName, fmi2Status status,
                           fmi2String category, fmi2String message, ...);
    Status check(fmi2Status status, const char* function) const;

    std::shared_ptr<const FmuPackage> mPackage;   // keeps the library's directory
    Logger mLogger;
    void* mLibrary = nullptr;
    Functions mFunctions;
    fmi2CallbackFunctions mCallbacks{};
    fmi2Component mComponent = nullptr;
    bool mInitialising = false;
    bool mInitialised = false;
};

} // namespace tlmhub::fmu
