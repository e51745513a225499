#pragma once
// An FMU file unpacked into a temporary directory of its own, with its model description
// read and checked. Components naming files of the same contents (the same SHA-256) share
// one package; its directory is removed when the last of them lets go.
#include "core/Status.h"
#include "fmu/ModelDescription.h"

#include <filesystem>
#include <memory>

namespace tlmhub::fmu {

class FmuPackage {
public:
    // `fmuFile` is already allowed by the load policy (fmu/FmuLoadPolicy.h).
    static Result<std::shared_ptr<const FmuPackage>> open(const std::filesystem::path& fmuFile);
    ~FmuPackage();
    FmuPackage(const FmuPackage&) = delete;
    FmuPackage& operator=(const FmuPackage&) = delete;

    const ModelDescription& description() const { return mDescription; }
    const std::filesystem::path& directory() const { return mDirectory; }
    // binaries/linux64/<modelIdentifier>.so
    std::filesystem::path libraryPath() const;
    // resources/ as the file:// URI fmi2Instantiate takes.
    std::string resourceUri() const;

private:
    explicit FmuPackage(std::filesystem::path directory) : mDirectory(std::move(directory)) {}

    std::filesystem::path mDirectory;
    ModelDescription mDescription;
};

} // namespace tlmhub::fmu
