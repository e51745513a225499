#pragma once
// An FMU file unpacked into a temporary directory of its own, with its model description
// read and checked. Components naming files of the same contents (the same SHA-256) share
// one package. Packages no model holds stay unpacked for the next load or compile, the most
// recently used kept, while their files take at most the cache's bytes together; a package is
// removed when it leaves the cache and the last component lets go. A file is hashed again
// only when its size or modification time changed.
#include "core/Status.h"
#include "fmu/ModelDescription.h"

#include <filesystem>
#include <memory>

namespace tlmhub::fmu {

class FmuPackage {
public:
    // `fmuFile` is already allowed by the load policy (fmu/FmuLoadPolicy.h).
    static Result<std::shared_ptr<const FmuPackage>> open(const std::filesystem::path& fmuFile);
    // The bytes unpacked packages no model holds may take (a server's --fmu-cache-bytes).
    static void setCacheBytes(std::uintmax_t bytes);
    static constexpr std::uintmax_t kDefaultCacheBytes = 256ull << 20;
    ~FmuPackage();
    FmuPackage(const FmuPackage&) = delete;
    FmuPackage& operator=(const FmuPackage&) = delete;

    const ModelDescription& description() const { return mDescription; }
    const std::filesystem::path& directory() const { return mDirectory; }
    std::uintmax_t unpackedBytes() const { return mBytes; }
    // binaries/linux64/<modelIdentifier>.so
    std::filesystem::path libraryPath() const;
    // resources/ as the file:// URI fmi2Instantiate takes.
    std::string resourceUri() const;

private:
    explicit FmuPackage(std::filesystem::path directory) : mDirectory(std::move(directory)) {}

    std::filesystem::path mDirectory;
    ModelDescription mDescription;
    std::uintmax_t mBytes = 0;
};

} // namespace tlmhub::fmu
