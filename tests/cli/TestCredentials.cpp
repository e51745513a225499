// The credentials file of `tlmhub-cli remote` (no server needed).
#include "cli/remote/Credentials.h"
#include "net/Url.h"
#include "server/TemporaryDirectory.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace tlmhub::cli::remote {
namespace {

using net::parseUrl;
using net::percentEncode;
using net::Url;

unsigned mode(const std::filesystem::path& path)
{
    struct stat s {};
    return ::stat(path.c_str(), &s) == 0 ? s.st_mode & 07777 : 0;
}

// XDG_CONFIG_HOME pointed at a fresh directory, TLMHUB_URL and TLMHUB_TOKEN unset, for one test.
class CredentialsFile : public ::testing::Test {
protected:
    void SetUp() override
    {
        mDir = test::makeTemporaryDirectory("tlmhub-credentials");
        ::setenv("XDG_CONFIG_HOME", mDir.c_str(), 1);
        ::unsetenv("TLMHUB_URL");
        ::unsetenv("TLMHUB_TOKEN");
    }
    void TearDown() override { std::filesystem::remove_all(mDir); }
    std::filesystem::path mDir;
};

TEST_F(CredentialsFile, IsWrittenPrivatelyAndReadBack)
{
    saveCredentials({"https://lab.example.org", "tlmh_first"});
    saveCredentials({"https://lab.example.org", "tlmh_second"});   // replaces the first
    const std::filesystem::path path = mDir / "tlmhub" / "credentials";
    EXPECT_EQ(credentialsPath(), path);
    EXPECT_EQ(mode(path), 0600u);
    EXPECT_EQ(mode(path.parent_path()), 0700u);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(nlohmann::json::parse(text.str()),
              (nlohmann::json{{"url", "https://lab.example.org"}, {"token", "tlmh_second"}}));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(path.parent_path()), {}), 1);   // no temporary left

    std::string error;
    const std::optional<Credentials> loaded = loadCredentials(error);
    ASSERT_TRUE(loaded) << error;
    EXPECT_EQ(loaded->url, "https://lab.example.org");
    EXPECT_EQ(loaded->token, "tlmh_second");
}

TEST_F(CredentialsFile, TheEnvironmentOverridesEachField)
{
    saveCredentials({"https://lab.example.org", "tlmh_file"});
    ::setenv("TLMHUB_TOKEN", "tlmh_env", 1);
    std::string error;
    std::optional<Credentials> loaded = loadCredentials(error);
    ASSERT_TRUE(loaded) << error;
    EXPECT_EQ(loaded->url, "https://lab.example.org");
    EXPECT_EQ(loaded->token, "tlmh_env");
    ::setenv("TLMHUB_URL", "http://127.0.0.1:8080", 1);
    loaded = loadCredentials(error);
    ASSERT_TRUE(loaded) << error;
    EXPECT_EQ(loaded->url, "http://127.0.0.1:8080");
}

TEST_F(CredentialsFile, MissingOrBrokenIsAnError)
{
    std::string error;
    EXPECT_FALSE(loadCredentials(error));
    EXPECT_NE(error.find("not logged in"), std::string::npos) << error;
    std::filesystem::create_directories(mDir / "tlmhub");
    std::ofstream(mDir / "tlmhub" / "credentials") << "{\"url\": 3}";
    EXPECT_FALSE(loadCredentials(error));
    EXPECT_NE(error.find("is not a credentials file"), std::string::npos) << error;
}

TEST(Url, ServerAddresses)
{
    std::string error;
    std::optional<Url> url = parseUrl("https://lab.example.org/tlmhub/api/v1/", error);
    ASSERT_TRUE(url) << error;
    EXPECT_TRUE(url->secure);
    EXPECT_EQ(url->host, "lab.example.org");
    EXPECT_EQ(url->port, "443");
    EXPECT_EQ(url->prefix, "/tlmhub");
    EXPECT_EQ(url->text(), "https://lab.example.org/tlmhub");
    url = parseUrl("http://[::1]:8080", error);
    ASSERT_TRUE(url) << error;
    EXPECT_EQ(url->host, "::1");
    EXPECT_EQ(url->authority(), "[::1]:8080");
    EXPECT_EQ(url->text(), "http://[::1]:8080");
    for (const char* bad : {"127.0.0.1:8080", "ftp://x", "http://", "http://x:0", "http://x:99999", "http://u@x",
                            "http://x/?q=1"})
        EXPECT_FALSE(parseUrl(bad, error)) << bad;
    EXPECT_EQ(percentEncode("Position Servo/1"), "Position%20Servo%2F1");
}

} // namespace
} // namespace tlmhub::cli::remote
