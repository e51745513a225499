#include "fmu/FmuInstance.h"

#include <dlfcn.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>

namespace tlmhub::fmu {

Result<std::unique_ptr<FmuInstance>> FmuInstance::create(std::shared_ptr<const FmuPackage> package,
                                                         const std::string& instanceName, Logger logger)
{
    const ModelDescription& description = package->description();
    const std::string library = package->libraryPath().string();
    std::unique_ptr<FmuInstance> instance(new FmuInstance(std::move(package), std::move(logger)));
    if (!std::filesystem::is_regular_file(library))
        return Status{StatusCode::IoError, "the FMU has no binaries/linux64/" + description.modelIdentifier + ".so"};
    instance->mLibrary = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!instance->mLibrary) {
        const char* why = ::dlerror();
        return Status{StatusCode::IoError, "cannot load the FMU's library: " + std::string(why ? why : "")};
    }
#define TLMHUB_FMI2_LOOKUP(name)                                                                               \
    instance->mFunctions.name = reinterpret_cast<name##TYPE*>(::dlsym(instance->mLibrary, #name));             \
    if (!instance->mFunctions.name)                                                                            \
        return Status{StatusCode::InvalidModel, "the FMU's library does not define " #name};
    TLMHUB_FMI2_COSIMULATION_FUNCTIONS(TLMHUB_FMI2_LOOKUP)
#undef TLMHUB_FMI2_LOOKUP

    FmuInstance& self = *instance;
    self.mCallbacks.logger = &FmuInstance::logFromFmu;
    self.mCallbacks.allocateMemory = &std::calloc;
    self.mCallbacks.freeMemory = &std::free;
    self.mCallbacks.componentEnvironment = &self;
    const std::string resources = self.mPackage->resourceUri();
    self.mComponent = self.mFunctions.fmi2Instantiate(instanceName.c_str(), fmi2CoSimulation, description.guid.c_str(),
                                                      resources.c_str(), &self.mCallbacks, fmi2False, fmi2False);
    if (!self.mComponent) return Status{StatusCode::InitFailed, "fmi2Instantiate failed"};
    return instance;
}

FmuInstance::~FmuInstance()
{
    if (mComponent) {
        if (mInitialised || mInitialising) mFunctions.fmi2Terminate(mComponent);
        mFunctions.fmi2FreeInstance(mComponent);
    }
    if (mLibrary) ::dlclose(mLibrary);
}

void FmuInstance::logFromFmu(fmi2ComponentEnvironment environment, fmi2String, fmi2Status status,
                             fmi2String category, fmi2String message, ...)
{
    auto* self = static_cast<FmuInstance*>(environment);
    if (!self || !self->mLogger || !message) return;
    // The message is a printf format (FMI 2.0 section 2.1.5).
    char text[1024];
    va_list arguments;
    va_start(arguments, message);
    std::vsnprintf(text, sizeof text, message, arguments);
    va_end(arguments);
    const LogLevel level = status == fmi2OK        ? LogLevel::Info
                           : status == fmi2Warning ? LogLevel::Warning
                                                   : LogLevel::Error;
    const std::string prefix = category && *category ? std::string("[") + category + "] " : std::string();
    self->mLogger(level, "FMU: " + prefix + text);
}

Status FmuInstance::check(fmi2Status status, const char* function) const
{
    if (status == fmi2OK || status == fmi2Warning) return Status::ok();
    return {StatusCode::InitFailed, std::string(function) + " failed (status " + std::to_string(status) + ")"};
}

Status FmuInstance::enterInitialization(double startTime)
{
    if (Status s = check(mFunctions.fmi2SetupExperiment(mComponent, fmi2False, 0.0, startTime, fmi2False, 0.0),
                         "fmi2SetupExperiment");
        !s)
        return s;
    if (Status s = check(mFunctions.fmi2EnterInitializationMode(mComponent), "fmi2EnterInitializationMode"); !s)
        return s;
    mInitialising = true;
    return Status::ok();
}

Status FmuInstance::exitInitialization()
{
    if (Status s = check(mFunctions.fmi2ExitInitializationMode(mComponent), "fmi2ExitInitializationMode"); !s)
        return s;
    mInitialising = false;
    mInitialised = true;
    return Status::ok();
}

bool FmuInstance::setReal(const std::vector<fmi2ValueReference>& references, const double* values) noexcept
{
    if (references.empty()) return true;
    const fmi2Status status = mFunctions.fmi2SetReal(mComponent, references.data(), references.size(), values);
    return status == fmi2OK || status == fmi2Warning;
}

bool FmuInstance::getReal(const std::vector<fmi2ValueReference>& references, double* values) noexcept
{
    if (references.empty()) return true;
    const fmi2Status status = mFunctions.fmi2GetReal(mComponent, references.data(), references.size(), values);
    return status == fmi2OK || status == fmi2Warning;
}

bool FmuInstance::doStep(double currentTime, double stepSize) noexcept
{
    const fmi2Status status = mFunctions.fmi2DoStep(mComponent, currentTime, stepSize, fmi2True);
    return status == fmi2OK || status == fmi2Warning;
}

} // namespace tlmhub::fmu
