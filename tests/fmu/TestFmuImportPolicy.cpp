// Where FMUs may load from: anywhere for the command-line tool, only under --fmu-dir for the
// server (not via "..", not via a link), nowhere by default.
#include "FmuImportTestSupport.h"

#include "core/hmf/HmfLoader.h"
#include "fmu/FmuLoadPolicy.h"

namespace tlmhub::fmu::test {
namespace {

class FmuImportPolicy : public ::testing::Test {
protected:
    void SetUp() override
    {
        fs::create_directory(fmuDir());
        fs::create_directory(outside());
        writeIntegratorFmu(fmuDir() / "integrator.fmu");
        writeIntegratorFmu(outside() / "other.fmu");
    }
    void TearDown() override { setFmuLoadPolicy(FmuLoadPolicy::nowhere()); }
    fs::path fmuDir() const { return dir.path() / "fmus"; }
    fs::path outside() const { return dir.path() / "elsewhere"; }
    FmuLoadPolicy serverPolicy() const
    {
        Result<FmuLoadPolicy> policy = FmuLoadPolicy::onlyUnder(fmuDir());
        EXPECT_TRUE(policy) << describe(policy.status());
        return policy ? *policy : FmuLoadPolicy::nowhere();
    }
    void expectRefused(const FmuLoadPolicy& policy, const std::string& path)
    {
        Result<fs::path> resolved = resolveFmuPath(policy, path, outside().string());
        ASSERT_FALSE(resolved) << path << " resolved to " << *resolved;
        EXPECT_EQ(resolved.status().code(), StatusCode::InvalidModel) << describe(resolved.status());
    }
    // A model with one FMIWrapper whose path is `path`, loaded from `directory`.
    LoadedModel loadModel(const std::string& path, const std::string& directory)
    {
        const std::string xml = R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="2.20.0"><system name="M">
            <objects><component typename="FMIWrapper" name="F"><parameters>
            <parameter name="path" value=")" + path + R"(" type="string"/></parameters></component></objects>
            </system></hopsanmodelfile>)";
        return loadHmfString(xml, directory);
    }

    TemporaryDirectory dir;
};

TEST_F(FmuImportPolicy, ServerResolvesRelativePathsInsideItsFmuDirectory)
{
    Result<fs::path> resolved = resolveFmuPath(serverPolicy(), "integrator.fmu", outside().string());
    ASSERT_TRUE(resolved) << describe(resolved.status());
    EXPECT_EQ(*resolved, fs::canonical(fmuDir() / "integrator.fmu"));
    Result<fs::path> absolute = resolveFmuPath(serverPolicy(), (fmuDir() / "integrator.fmu").string(), "");
    EXPECT_TRUE(absolute) << describe(absolute.status());
}

TEST_F(FmuImportPolicy, ServerRefusesPathsOutsideItsFmuDirectory)
{
    expectRefused(serverPolicy(), (outside() / "other.fmu").string());
    expectRefused(serverPolicy(), "../elsewhere/other.fmu");
    expectRefused(serverPolicy(), "missing.fmu");
    fs::create_symlink(outside() / "other.fmu", fmuDir() / "link.fmu");
    expectRefused(serverPolicy(), "link.fmu");
    fs::create_directory_symlink(outside(), fmuDir() / "linkdir");
    expectRefused(serverPolicy(), "linkdir/other.fmu");
}

TEST_F(FmuImportPolicy, NowhereRefusesEverything)
{
    expectRefused(FmuLoadPolicy::nowhere(), (fmuDir() / "integrator.fmu").string());
    EXPECT_FALSE(FmuLoadPolicy::onlyUnder(dir.path() / "no-such-dir"));
}

TEST_F(FmuImportPolicy, CommandLineLoadsFromAnywhereRelativeToTheModel)
{
    Result<fs::path> resolved = resolveFmuPath(FmuLoadPolicy::anywhere(), "other.fmu", outside().string());
    ASSERT_TRUE(resolved) << describe(resolved.status());
    EXPECT_EQ(*resolved, fs::canonical(outside() / "other.fmu"));
    Result<fs::path> missing = resolveFmuPath(FmuLoadPolicy::anywhere(), "missing.fmu", outside().string());
    EXPECT_EQ(missing.status().code(), StatusCode::NotFound);
}

TEST_F(FmuImportPolicy, AModelNamingAnFmuOutsideTheServersDirectoryFailsToLoadWithAClearError)
{
    setFmuLoadPolicy(serverPolicy());
    LoadedModel refused = loadModel("../elsewhere/other.fmu", outside().string());
    ASSERT_TRUE(refused.hasErrors());
    EXPECT_NE(refused.firstError().find("is not a file in this server's FMU directory"), std::string::npos)
        << refused.firstError();
    LoadedModel allowed = loadModel("integrator.fmu", "");
    EXPECT_FALSE(allowed.hasErrors()) << allowed.firstError();
    ASSERT_TRUE(allowed.root->component("F")->port("u"));

    setFmuLoadPolicy(FmuLoadPolicy::nowhere());
    LoadedModel none = loadModel("integrator.fmu", "");
    ASSERT_TRUE(none.hasErrors());
    EXPECT_NE(none.firstError().find("loading FMUs is disabled"), std::string::npos) << none.firstError();
}

} // namespace
} // namespace tlmhub::fmu::test
