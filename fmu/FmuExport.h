#pragma once
// A model exported as an FMI 2.0 co-simulation FMU: a zip holding
//   modelDescription.xml                   the interface (fmu/ModelInterface.h's rules)
//   binaries/linux64/<modelIdentifier>.so  the runtime library (fmu/runtime/), renamed
//   binaries/linux64/<its libraries>       what it needs besides glibc and the GCC runtime
//   resources/model.hmf                    the model text as given
//   resources/parameters.txt               the offered component parameters, one per line
#include "core/Status.h"
#include "fmu/ModelInterface.h"

#include <filesystem>
#include <string>

namespace tlmhub::fmu {

// The runtime's file name, and the directory next to it with the libraries each FMU carries.
inline constexpr const char* kRuntimeFileName = "libtlmhub-fmu-runtime.so";
inline constexpr const char* kRuntimeLibrariesDirectory = "fmu-runtime-libs";

// The zip's bytes, or why the model cannot be exported (it does not load, compile, or its
// interface breaks a rule). `modelFileName` names the model in messages and resolves
// relative paths while checking it.
Result<std::string> exportFmu(const std::string& hmfText, const std::string& modelFileName,
                              const InterfaceOptions& options, const std::filesystem::path& runtimeLibrary);

// Where the runtime library is: $TLMHUB_FMU_RUNTIME if set, else next to the running
// executable, else in ../lib/tlmhub/ from it. `argv0` is used only when /proc/self/exe
// cannot be read. io_error naming the places looked at if it is in none.
Result<std::filesystem::path> findFmuRuntime(const std::string& argv0);

} // namespace tlmhub::fmu
