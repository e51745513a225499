#include "fmu/FmuExport.h"

#include "core/hmf/HmfLoader.h"
#include "fmu/Guid.h"
#include "fmu/ModelDescription.h"

#include <zip.h>

#include <cstdlib>
#include <fstream>
#include <list>
#include <sstream>

namespace tlmhub::fmu {
namespace {

namespace fs = std::filesystem;

Result<std::string> readBinaryFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    if (!(in && bytes << in.rdbuf()))
        return Status{StatusCode::IoError, "cannot read " + path.string()};
    return bytes.str();
}

// Deflate's fastest level: the runtime library, most of an FMU's bytes, compresses 2.8 times
// faster than at the default level (5 MB: 0.19 s against 0.53 s) into a zip 12 % larger.
constexpr zip_uint32_t kDeflateLevel = 1;

// A zip built in memory. Entries' bytes are kept until the archive is closed, as libzip
// reads them only then.
class ZipWriter {
public:
    ZipWriter()
    {
        zip_error_t error;
        zip_error_init(&error);
        mSource = zip_source_buffer_create(nullptr, 0, 0, &error);
        if (mSource)
            mArchive = zip_open_from_source(mSource, ZIP_TRUNCATE, &error);
        if (mSource && !mArchive)
            zip_source_free(mSource);
        else if (mSource)
            zip_source_keep(mSource);   // the bytes are read from it after zip_close
        zip_error_fini(&error);
    }
    ~ZipWriter()
    {
        if (mArchive)
            zip_discard(mArchive);
        if (mSource)
            zip_source_free(mSource);
    }
    ZipWriter(const ZipWriter&) = delete;
    ZipWriter& operator=(const ZipWriter&) = delete;

    bool add(const std::string& name, std::string bytes)
    {
        if (!mArchive)
            return false;
        const std::string& kept = mContents.emplace_back(std::move(bytes));
        zip_source_t* entry = zip_source_buffer(mArchive, kept.data(), kept.size(), 0);
        if (!entry)
            return false;
        const zip_int64_t index = zip_file_add(mArchive, name.c_str(), entry, ZIP_FL_ENC_UTF_8);
        if (index < 0) {
            zip_source_free(entry);
            return false;
        }
        return zip_set_file_compression(mArchive, static_cast<zip_uint64_t>(index), ZIP_CM_DEFLATE,
                                        kDeflateLevel) == 0;
    }

    Result<std::string> finish()
    {
        if (!mArchive || zip_close(mArchive) != 0)
            return Status{StatusCode::IoError, std::string("cannot write the FMU's zip: ") +
                                                   (mArchive ? zip_strerror(mArchive) : "no archive")};
        mArchive = nullptr;
        std::string bytes;
        zip_stat_t stat;
        if (zip_source_stat(mSource, &stat) != 0 || zip_source_open(mSource) != 0)
            return Status{StatusCode::IoError, "cannot read the FMU's zip back"};
        bytes.resize(stat.size);
        const zip_int64_t read = zip_source_read(mSource, bytes.data(), bytes.size());
        zip_source_close(mSource);
        if (read < 0 || static_cast<zip_uint64_t>(read) != stat.size)
            return Status{StatusCode::IoError, "cannot read the FMU's zip back"};
        return bytes;
    }

private:
    zip_source_t* mSource = nullptr;
    zip_t* mArchive = nullptr;
    std::list<std::string> mContents;   // a list: adding never moves the kept bytes
};

std::string joinedLines(const std::vector<std::string>& lines)
{
    std::string text;
    for (const std::string& line : lines)
        text += line + "\n";
    return text;
}

} // namespace

Result<std::string> exportFmu(const std::string& hmfText, const std::string& modelFileName,
                              const InterfaceOptions& options, const fs::path& runtimeLibrary)
{
    LoadedModel loaded = loadHmfString(hmfText, fs::path(modelFileName).parent_path().string(), modelFileName);
    if (loaded.hasErrors())
        return loaded.status();
    const Model model(std::move(loaded.root));
    Result<ModelInterface> described = describeInterface(model.root(), options);
    if (!described)
        return described.status();
    // Also refuses a model that does not compile or initialise: it would fail in every importer.
    if (Status started = takeInputStartsFromInitialisation(*described, model); !started)
        return started;

    ModelDescription& description = described->description;
    description.guid = guidOfModel(hmfText, options.parameters);
    description.generationTool = "tlmhub " TLMHUB_VERSION;

    Result<std::string> runtime = readBinaryFile(runtimeLibrary);
    if (!runtime)
        return runtime.status();
    ZipWriter zip;
    bool ok = zip.add("modelDescription.xml", writeModelDescription(description)) &&
              zip.add("binaries/linux64/" + description.modelIdentifier + ".so", std::move(*runtime)) &&
              zip.add("resources/model.hmf", hmfText) &&
              zip.add("resources/parameters.txt", joinedLines(options.parameters));
    const fs::path libraries = runtimeLibrary.parent_path() / kRuntimeLibrariesDirectory;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(libraries, error)) {
        Result<std::string> library = readBinaryFile(entry.path());
        if (!library)
            return library.status();
        ok = ok && zip.add("binaries/linux64/" + entry.path().filename().string(), std::move(*library));
    }
    if (error)
        return Status{StatusCode::IoError, "cannot list " + libraries.string() + " (the runtime's libraries)"};
    if (!ok)
        return Status{StatusCode::IoError, "cannot add a file to the FMU's zip"};
    return zip.finish();
}

Result<fs::path> findFmuRuntime(const std::string& argv0)
{
    if (const char* overridden = std::getenv("TLMHUB_FMU_RUNTIME"); overridden && *overridden) {
        if (fs::is_regular_file(overridden))
            return fs::path(overridden);
        return Status{StatusCode::IoError,
                      std::string("TLMHUB_FMU_RUNTIME names ") + overridden + ", which is not a file"};
    }
    std::error_code error;
    fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (error)
        executable = fs::absolute(argv0, error);
    const fs::path directory = executable.parent_path();
    const fs::path candidates[] = {directory / kRuntimeFileName, directory / ".." / "lib" / "tlmhub" / kRuntimeFileName};
    for (const fs::path& candidate : candidates)
        if (fs::is_regular_file(candidate, error))
            return candidate.lexically_normal();
    return Status{StatusCode::IoError, std::string("the FMU runtime ") + kRuntimeFileName + " is neither in " +
                                           candidates[0].parent_path().string() + " nor in " +
                                           candidates[1].parent_path().lexically_normal().string() +
                                           " (build the target tlmhub-fmu-runtime, or set TLMHUB_FMU_RUNTIME)"};
}

} // namespace tlmhub::fmu
