#include "fmu/ZipExtraction.h"

#include <zip.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub::fmu {

namespace {

namespace fs = std::filesystem;

Status refuse(const std::string& entry, const std::string& why)
{
    return {StatusCode::InvalidModel, "zip entry '" + entry + "': " + why};
}

struct ZipCloser {
    void operator()(zip_t* archive) const { zip_discard(archive); }
};
struct ZipFileCloser {
    void operator()(zip_file_t* file) const { zip_fclose(file); }
};

// A relative name of plain components: nothing that could leave the destination or mean
// something else on another system.
Status checkName(const std::string& name)
{
    if (name.empty()) return refuse(name, "empty name");
    if (name.front() == '/') return refuse(name, "absolute path");
    for (unsigned char c : name) {
        if (c < 0x20 || c == 0x7f) return refuse(name, "control character in the name");
        if (c == '\\') return refuse(name, "backslash in the name");
    }
    std::string_view rest(name);
    if (rest.back() == '/') rest.remove_suffix(1);   // a directory entry
    while (true) {
        const std::size_t slash = rest.find('/');
        const std::string_view component = rest.substr(0, slash);
        if (component.empty()) return refuse(name, "empty path component");
        if (component == "." || component == "..") return refuse(name, "'.' or '..' path component");
        if (slash == std::string_view::npos) break;
        rest.remove_prefix(slash + 1);
    }
    return Status::ok();
}

// Only plain files and directories: a Unix-made archive states the entry's file type.
bool isSpecialEntry(zip_t* archive, zip_uint64_t index)
{
    zip_uint8_t system = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(archive, index, 0, &system, &attributes) != 0) return true;
    if (system != ZIP_OPSYS_UNIX) return false;
    const mode_t mode = static_cast<mode_t>(attributes >> 16);
    const mode_t type = mode & S_IFMT;
    return type != 0 && type != S_IFREG && type != S_IFDIR;
}

bool isInside(const fs::path& root, const fs::path& candidate)
{
    const std::string prefix = root.string() + "/";
    return candidate.string().rfind(prefix, 0) == 0;
}

// Inflates one entry into a new file (never an existing one, never through a link), counting
// the bytes that really come out.
Status writeEntry(zip_t* archive, zip_uint64_t index, const std::string& name, const fs::path& target,
                  const ExtractionLimits& limits, std::uint64_t& total)
{
    std::unique_ptr<zip_file_t, ZipFileCloser> in(zip_fopen_index(archive, index, 0));
    if (!in) return {StatusCode::IoError, "zip entry '" + name + "': " + zip_strerror(archive)};
    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) return {StatusCode::IoError, "zip entry '" + name + "': cannot create " + target.string()};
    std::vector<char> buffer(64 * 1024);
    std::uint64_t written = 0;
    Status status;
    while (status) {
        const zip_int64_t got = zip_fread(in.get(), buffer.data(), buffer.size());
        if (got < 0) {
            status = {StatusCode::InvalidModel, "zip entry '" + name + "': " + zip_file_strerror(in.get())};
            break;
        }
        if (got == 0) break;
        written += static_cast<std::uint64_t>(got);
        total += static_cast<std::uint64_t>(got);
        if (written > limits.maxFileBytes)
            status = refuse(name, "inflates to more than " + std::to_string(limits.maxFileBytes) + " bytes");
        else if (total > limits.maxTotalBytes)
            status = refuse(name, "the archive inflates to more than " + std::to_string(limits.maxTotalBytes) +
                                      " bytes");
        else if (::write(fd, buffer.data(), static_cast<std::size_t>(got)) != got)
            status = {StatusCode::IoError, "zip entry '" + name + "': cannot write " + target.string()};
    }
    if (::close(fd) != 0 && status) status = {StatusCode::IoError, "zip entry '" + name + "': cannot write"};
    return status;
}

} // namespace

Status extractZip(const fs::path& archivePath, const fs::path& destination, const ExtractionLimits& limits)
{
    std::error_code ec;
    const fs::path root = fs::canonical(destination, ec);
    if (ec || !fs::is_directory(root) || !fs::is_empty(root))
        return {StatusCode::IoError, "extraction directory " + destination.string() + " is not an empty directory"};

    int error = 0;
    std::unique_ptr<zip_t, ZipCloser> archive(zip_open(archivePath.c_str(), ZIP_RDONLY, &error));
    if (!archive) {
        zip_error_t zipError;
        zip_error_init_with_code(&zipError, error);
        Status status{StatusCode::IoError,
                      "cannot open " + archivePath.filename().string() + " as a zip archive: " + zip_error_strerror(&zipError)};
        zip_error_fini(&zipError);
        return status;
    }
    const zip_int64_t count = zip_get_num_entries(archive.get(), 0);
    if (count < 0 || static_cast<std::uint64_t>(count) > limits.maxEntries)
        return {StatusCode::InvalidModel, archivePath.filename().string() + " has more than " +
                                              std::to_string(limits.maxEntries) + " entries"};

    std::set<std::string> seen;
    std::uint64_t total = 0;
    for (zip_uint64_t index = 0; index < static_cast<zip_uint64_t>(count); ++index) {
        const char* rawName = zip_get_name(archive.get(), index, ZIP_FL_ENC_RAW);
        if (!rawName) return {StatusCode::InvalidModel, "zip entry " + std::to_string(index) + " has no name"};
        const std::string name = rawName;
        if (Status ok = checkName(name); !ok) return ok;
        const bool isDirectory = name.back() == '/';
        const std::string key = isDirectory ? name.substr(0, name.size() - 1) : name;
        if (!seen.insert(key).second) return refuse(name, "the name occurs twice");
        if (isSpecialEntry(archive.get(), index)) return refuse(name, "a link or special file");

        const fs::path target = root / key;
        // The parent must exist as a real directory inside the destination (a link
        // planted by an earlier entry cannot be: links are refused; checked anyway).
        fs::create_directories(target.parent_path(), ec);
        if (ec) return {StatusCode::IoError, "zip entry '" + name + "': cannot create its directory"};
        const fs::path resolved = fs::weakly_canonical(target, ec);
        if (ec || !isInside(root, resolved)) return refuse(name, "leaves the extraction directory");
        if (isDirectory) {
            fs::create_directory(target, ec);
            if (ec || fs::is_symlink(target)) return {StatusCode::IoError, "zip entry '" + name + "': cannot create"};
            continue;
        }
        if (Status written = writeEntry(archive.get(), index, name, target, limits, total); !written)
            return written;
    }
    return Status::ok();
}

} // namespace tlmhub::fmu
