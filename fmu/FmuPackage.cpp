#include "fmu/FmuPackage.h"

#include "core/Sha256.h"
#include "fmu/ZipExtraction.h"

#include <stdlib.h>

#include <fstream>
#include <list>
#include <map>
#include <mutex>
#include <sstream>

namespace tlmhub::fmu {

namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kMaxFmuFileBytes = 1ull << 30;
constexpr std::uintmax_t kMaxDescriptionFileBytes = 16ull << 20;

// Files hashed before, by path: hashed again when their size or modification time changes.
constexpr std::size_t kMaxRememberedDigests = 4096;
struct KnownDigest {
    std::uintmax_t size;
    fs::file_time_type modified;
    std::string digest;
};

// All under gCacheMutex.
std::mutex gCacheMutex;
std::map<std::string, std::weak_ptr<const FmuPackage>> gCache;   // by the file's SHA-256
std::map<std::string, KnownDigest> gDigests;
// Strong references that keep packages unpacked, the most recently used first.
std::list<std::shared_ptr<const FmuPackage>> gKept;
std::uintmax_t gKeptBytes = 0;
std::uintmax_t gCacheBytes = FmuPackage::kDefaultCacheBytes;

void trimKept()
{
    while (gKeptBytes > gCacheBytes && !gKept.empty()) {
        gKeptBytes -= gKept.back()->unpackedBytes();
        gKept.pop_back();
    }
}

void keep(const std::shared_ptr<const FmuPackage>& package)
{
    for (auto it = gKept.begin(); it != gKept.end(); ++it) {
        if (*it == package) {
            gKept.splice(gKept.begin(), gKept, it);
            return;
        }
    }
    gKept.push_front(package);
    gKeptBytes += package->unpackedBytes();
    trimKept();
}

std::uintmax_t directoryBytes(const fs::path& directory)
{
    std::uintmax_t bytes = 0;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(directory, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        if (it->is_regular_file(ec)) bytes += it->file_size(ec);
    return bytes;
}

Result<std::string> fileDigest(const fs::path& file)
{
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) return Status{StatusCode::IoError, "cannot read " + file.string()};
    if (size > kMaxFmuFileBytes)
        return Status{StatusCode::InvalidModel, file.filename().string() + " is larger than 1 GiB"};
    const fs::file_time_type modified = fs::last_write_time(file, ec);
    if (ec) return Status{StatusCode::IoError, "cannot read " + file.string()};
    {
        std::lock_guard lock(gCacheMutex);
        const auto known = gDigests.find(file.string());
        if (known != gDigests.end() && known->second.size == size && known->second.modified == modified)
            return known->second.digest;
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) return Status{StatusCode::IoError, "cannot read " + file.string()};
    Sha256 hash;
    std::string buffer(1 << 16, '\0');
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        hash.update(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())));
    }
    std::string digest = hash.hexDigest();
    std::lock_guard lock(gCacheMutex);
    if (gDigests.size() >= kMaxRememberedDigests) gDigests.clear();
    gDigests[file.string()] = {size, modified, digest};
    return digest;
}

Result<fs::path> makeTemporaryDirectory()
{
    std::string pattern = (fs::temp_directory_path() / "tlmhub-fmu-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) return Status{StatusCode::IoError, "cannot create a temporary directory"};
    return fs::path(pattern);
}

// Characters a file URI may carry as they are; the rest percent-encoded.
std::string fileUri(const fs::path& directory)
{
    static const char* hex = "0123456789ABCDEF";
    std::string uri = "file://";
    for (unsigned char c : directory.string() + "/") {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                           c == '/' || c == '-' || c == '_' || c == '.' || c == '~';
        if (plain) {
            uri += static_cast<char>(c);
        } else {
            uri += '%';
            uri += hex[c >> 4];
            uri += hex[c & 15];
        }
    }
    return uri;
}

} // namespace

Result<std::shared_ptr<const FmuPackage>> FmuPackage::open(const fs::path& fmuFile)
{
    Result<std::string> digest = fileDigest(fmuFile);
    if (!digest) return digest.status();
    std::lock_guard lock(gCacheMutex);
    if (auto found = gCache.find(*digest); found != gCache.end()) {
        if (std::shared_ptr<const FmuPackage> shared = found->second.lock()) {
            keep(shared);
            return shared;
        }
    }

    Result<fs::path> directory = makeTemporaryDirectory();
    if (!directory) return directory.status();
    std::shared_ptr<FmuPackage> package(new FmuPackage(*directory));
    const std::string name = fmuFile.filename().string();
    if (Status extracted = extractZip(fmuFile, package->mDirectory); !extracted)
        return Status{extracted.code(), name + ": " + extracted.message()};

    const fs::path descriptionFile = package->mDirectory / "modelDescription.xml";
    std::error_code ec;
    if (!fs::is_regular_file(descriptionFile, ec) || fs::file_size(descriptionFile, ec) > kMaxDescriptionFileBytes)
        return Status{StatusCode::InvalidModel, name + " has no modelDescription.xml (or one over 16 MiB)"};
    std::ifstream in(descriptionFile, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    Result<ModelDescription> description = parseModelDescription(text.str());
    if (!description) return Status{description.status().code(), name + ": " + description.status().message()};
    package->mDescription = std::move(*description);
    package->mBytes = directoryBytes(package->mDirectory);

    for (auto it = gCache.begin(); it != gCache.end();) it = it->second.expired() ? gCache.erase(it) : std::next(it);
    gCache[*digest] = package;
    std::shared_ptr<const FmuPackage> shared = std::move(package);
    keep(shared);
    return shared;
}

void FmuPackage::setCacheBytes(std::uintmax_t bytes)
{
    std::lock_guard lock(gCacheMutex);
    gCacheBytes = bytes;
    trimKept();
}

FmuPackage::~FmuPackage()
{
    std::error_code ec;
    fs::remove_all(mDirectory, ec);
}

fs::path FmuPackage::libraryPath() const
{
    return mDirectory / "binaries" / "linux64" / (mDescription.modelIdentifier + ".so");
}

std::string FmuPackage::resourceUri() const
{
    return fileUri(mDirectory / "resources");
}

} // namespace tlmhub::fmu
