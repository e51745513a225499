// extractZip against hostile archives: each is refused naming the entry, and nothing lands
// outside the extraction directory.
#include "FmuImportTestSupport.h"

#include "fmu/ZipExtraction.h"

namespace tlmhub::fmu::test {
namespace {

class ZipExtraction : public ::testing::Test {
protected:
    fs::path archive() const { return dir.path() / "archive.zip"; }
    fs::path destination() const { return dir.path() / "out"; }
    // Extracts `entries` into a new directory; the outcome.
    Status extract(const std::vector<ZipEntry>& entries, const ExtractionLimits& limits = {})
    {
        writeZip(archive(), entries);
        fs::remove_all(destination());
        fs::create_directory(destination());
        return extractZip(archive(), destination(), limits);
    }
    void expectRefused(const Status& status, const std::string& why)
    {
        ASSERT_FALSE(status) << "accepted; expected: " << why;
        EXPECT_EQ(status.code(), StatusCode::InvalidModel) << describe(status);
        EXPECT_NE(status.message().find(why), std::string::npos) << status.message();
    }

    TemporaryDirectory dir;
};

TEST_F(ZipExtraction, ExtractsFilesAndDirectories)
{
    ASSERT_TRUE(extract({{"modelDescription.xml", "<x/>"}, {"resources/", ""}, {"binaries/linux64/a.so", "bin"}}));
    EXPECT_EQ(readFile(destination() / "modelDescription.xml"), "<x/>");
    EXPECT_EQ(readFile(destination() / "binaries/linux64/a.so"), "bin");
    EXPECT_TRUE(fs::is_directory(destination() / "resources"));
}

TEST_F(ZipExtraction, RefusesZipSlip)
{
    expectRefused(extract({{"../x", "evil"}}), "zip entry '../x': '.' or '..' path component");
    EXPECT_FALSE(fs::exists(dir.path() / "x"));
    expectRefused(extract({{"a/../../x", "evil"}}), "'.' or '..' path component");
}

TEST_F(ZipExtraction, RefusesAbsolutePaths)
{
    expectRefused(extract({{"/etc/x", "evil"}}), "zip entry '/etc/x': absolute path");
}

TEST_F(ZipExtraction, RefusesBackslashesAndControlCharacters)
{
    expectRefused(extract({{"a\\..\\..\\x", "evil"}}), "backslash");
    expectRefused(extract({{"a\nb", "evil"}}), "control character");
    expectRefused(extract({{"a//b", "evil"}}), "empty path component");
}

TEST_F(ZipExtraction, RefusesLinks)
{
    expectRefused(extract({{"link", "/etc/passwd", true}}), "zip entry 'link': a link or special file");
    EXPECT_FALSE(fs::exists(destination() / "link"));
}

TEST_F(ZipExtraction, RefusesDuplicateNames)
{
    // libzip writes no duplicates: write two names, then make the second one the first.
    writeZip(archive(), {{"a.txt", "one"}, {"b.txt", "two"}});
    std::string bytes = readFile(archive());
    for (std::size_t at = bytes.find("b.txt"); at != std::string::npos; at = bytes.find("b.txt", at)) bytes[at] = 'a';
    writeFile(archive(), bytes);
    fs::create_directory(destination());
    expectRefused(extractZip(archive(), destination()), "zip entry 'a.txt': the name occurs twice");
    expectRefused(extract({{"d/", ""}, {"d", "file"}}), "the name occurs twice");
}

TEST_F(ZipExtraction, RefusesTooManyEntries)
{
    std::vector<ZipEntry> entries;
    for (int i = 0; i < 11; ++i) entries.push_back({std::to_string(i) + ".txt", "x"});
    ExtractionLimits limits;
    limits.maxEntries = 10;
    expectRefused(extract(entries, limits), "more than 10 entries");
}

TEST_F(ZipExtraction, RefusesAZipBombByTheBytesInflated)
{
    // 64 MiB of zeros deflate to about 64 KiB.
    const std::string zeros(64u << 20, '\0');
    ExtractionLimits limits;
    limits.maxTotalBytes = 16u << 20;
    expectRefused(extract({{"bomb", zeros}}, limits), "the archive inflates to more than 16777216 bytes");
    EXPECT_LT(fs::file_size(archive()), 1u << 20);
    limits.maxTotalBytes = 1ull << 30;
    limits.maxFileBytes = 1u << 20;
    expectRefused(extract({{"bomb", zeros}}, limits), "zip entry 'bomb': inflates to more than 1048576 bytes");
}

TEST_F(ZipExtraction, NeedsAnEmptyDestination)
{
    fs::create_directory(destination());
    writeFile(destination() / "old", "x");
    writeZip(archive(), {{"a", "b"}});
    const Status status = extractZip(archive(), destination());
    EXPECT_EQ(status.code(), StatusCode::IoError);
}

TEST_F(ZipExtraction, RefusesWhatIsNotAZip)
{
    writeFile(archive(), "not a zip at all");
    fs::create_directory(destination());
    const Status status = extractZip(archive(), destination());
    EXPECT_EQ(status.code(), StatusCode::IoError);
    EXPECT_NE(status.message().find("as a zip archive"), std::string::npos) << status.message();
}

} // namespace
} // namespace tlmhub::fmu::test
