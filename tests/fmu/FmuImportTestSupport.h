#pragma once
// What the FMU import tests share: temporary directories, zip archives written with libzip
// (hostile ones too), and .fmu files made from the hand-written integrator
// (tests/fmu/handwritten/).
#include <gtest/gtest.h>
#include <zip.h>

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tlmhub::fmu::test {

namespace fs = std::filesystem;

class TemporaryDirectory {
public:
    TemporaryDirectory()
    {
        std::string pattern = (fs::temp_directory_path() / "tlmhub-fmu-test-XXXXXX").string();
        if (::mkdtemp(pattern.data())) mPath = pattern;
        EXPECT_FALSE(mPath.empty()) << "cannot create a temporary directory";
    }
    ~TemporaryDirectory()
    {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

inline std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << "cannot read " << path;
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void writeFile(const fs::path& path, const std::string& content)
{
    std::ofstream out(path, std::ios::binary);
    out << content;
    ASSERT_TRUE(out) << "cannot write " << path;
}

struct ZipEntry {
    std::string name;
    std::string content;
    bool symlink = false;   // a Unix symbolic link to `content`
};

// Writes the entries as they are: libzip does not question names, so hostile ones go in.
inline void writeZip(const fs::path& path, const std::vector<ZipEntry>& entries)
{
    int error = 0;
    zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    ASSERT_TRUE(archive) << "zip_open " << error;
    for (const ZipEntry& entry : entries) {
        zip_source_t* source = zip_source_buffer(archive, entry.content.data(), entry.content.size(), 0);
        ASSERT_TRUE(source);
        const zip_int64_t index = zip_file_add(archive, entry.name.c_str(), source, ZIP_FL_ENC_RAW);
        ASSERT_GE(index, 0) << entry.name << ": " << zip_strerror(archive);
        if (entry.symlink)
            zip_file_set_external_attributes(archive, static_cast<zip_uint64_t>(index), 0, ZIP_OPSYS_UNIX,
                                             (0120777u) << 16);
    }
    ASSERT_EQ(zip_close(archive), 0) << zip_strerror(archive);
}

inline fs::path sourceDir() { return TLMHUB_SOURCE_DIR; }

inline std::string integratorDescription()
{
    return readFile(sourceDir() / "tests/fmu/handwritten/integrator/modelDescription.xml");
}

// integrator.fmu as an exporter would pack it; the parts may be swapped for broken ones.
inline void writeIntegratorFmu(const fs::path& path, const std::string& description = integratorDescription(),
                               const std::string& library = TLMHUB_TEST_FMU_LIBRARY,
                               const std::string& libraryName = "binaries/linux64/integrator.so")
{
    std::vector<ZipEntry> entries{{"modelDescription.xml", description}};
    if (!library.empty()) entries.push_back({libraryName, readFile(library)});
    writeZip(path, entries);
}

} // namespace tlmhub::fmu::test
