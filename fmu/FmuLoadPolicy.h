#pragma once
// Where FMUs may be loaded from. An FMU is native code that runs inside this process, so
// the choice belongs to whoever starts the process, not to a model:
//  - the command-line tool loads any FMU its user's model names (Anywhere);
//  - the server loads only FMUs under the directory its administrator names at start-up
//    (--fmu-dir: OnlyUnder), and none without one (Nowhere, the default).
// One policy per process, set before models load.
#include "core/Status.h"

#include <filesystem>
#include <string>

namespace tlmhub::fmu {

struct FmuLoadPolicy {
    enum class Scope { Nowhere, Anywhere, OnlyUnder } scope = Scope::Nowhere;
    std::filesystem::path directory;   // OnlyUnder: canonical

    static FmuLoadPolicy nowhere() { return {}; }
    static FmuLoadPolicy anywhere() { return {Scope::Anywhere, {}}; }
    // Fails (IoError) when `directory` is not an existing directory.
    static Result<FmuLoadPolicy> onlyUnder(const std::filesystem::path& directory);
};

void setFmuLoadPolicy(FmuLoadPolicy policy);
FmuLoadPolicy fmuLoadPolicy();

// The canonical file a model's FMU path names under `policy`: a relative path resolves
// against the model's directory (Anywhere) or the FMU directory (OnlyUnder), and must stay
// inside the latter after following links. NotFound for a missing file; InvalidModel when
// the policy forbids it.
Result<std::filesystem::path> resolveFmuPath(const FmuLoadPolicy& policy, const std::string& path,
                                             const std::string& modelDirectory);

} // namespace tlmhub::fmu
