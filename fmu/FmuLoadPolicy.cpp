#include "fmu/FmuLoadPolicy.h"

#include <mutex>

namespace tlmhub::fmu {

namespace fs = std::filesystem;

namespace {

std::mutex gPolicyMutex;
FmuLoadPolicy gPolicy;

} // namespace

Result<FmuLoadPolicy> FmuLoadPolicy::onlyUnder(const fs::path& directory)
{
    std::error_code ec;
    fs::path canonical = fs::canonical(directory, ec);
    if (ec || !fs::is_directory(canonical))
        return Status{StatusCode::IoError, "FMU directory " + directory.string() + " is not a directory"};
    return FmuLoadPolicy{Scope::OnlyUnder, std::move(canonical)};
}

void setFmuLoadPolicy(FmuLoadPolicy policy)
{
    std::lock_guard lock(gPolicyMutex);
    gPolicy = std::move(policy);
}

FmuLoadPolicy fmuLoadPolicy()
{
    std::lock_guard lock(gPolicyMutex);
    return gPolicy;
}

Result<fs::path> resolveFmuPath(const FmuLoadPolicy& policy, const std::string& path,
                                const std::string& modelDirectory)
{
    if (path.empty()) return Status{StatusCode::InvalidParameter, "no FMU file given (parameter path)"};
    if (path.find('\0') != std::string::npos) return Status{StatusCode::InvalidParameter, "FMU path has a NUL"};
    fs::path requested(path);
    switch (policy.scope) {
    case FmuLoadPolicy::Scope::Nowhere:
        return Status{StatusCode::InvalidModel,
                      "loading FMUs is disabled here ('" + path + "'; a server loads them only from its --fmu-dir)"};
    case FmuLoadPolicy::Scope::Anywhere:
        if (requested.is_relative() && !modelDirectory.empty()) requested = fs::path(modelDirectory) / requested;
        break;
    case FmuLoadPolicy::Scope::OnlyUnder:
        if (requested.is_relative()) requested = policy.directory / requested;
        break;
    }
    std::error_code ec;
    const fs::path canonical = fs::canonical(requested, ec);
    const bool isFile = !ec && fs::is_regular_file(canonical);
    // The same answer for a missing file and one outside: no probing of the host's files.
    if (policy.scope == FmuLoadPolicy::Scope::OnlyUnder &&
        (!isFile || canonical.string().rfind(policy.directory.string() + "/", 0) != 0))
        return Status{StatusCode::InvalidModel, "FMU '" + path + "' is not a file in this server's FMU directory"};
    if (!isFile) return Status{StatusCode::NotFound, "no FMU file '" + path + "'"};
    return canonical;
}

} // namespace tlmhub::fmu
