// Broken FMUs fail with an error that says what is wrong, at load or at initialisation, and
// nothing crashes.
#include "FmuImportTestSupport.h"

#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "fmu/FmuLoadPolicy.h"

namespace tlmhub::fmu::test {
namespace {

class FmuImportBroken : public ::testing::Test {
protected:
    void SetUp() override { setFmuLoadPolicy(FmuLoadPolicy::anywhere()); }
    void TearDown() override { setFmuLoadPolicy(FmuLoadPolicy::nowhere()); }
    fs::path fmu() const { return dir.path() / "broken.fmu"; }
    LoadedModel load()
    {
        const std::string xml = R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="2.20.0"><system name="M">
            <simulationtime stop="0.01" timestep="0.001" start="0"/>
            <objects><component typename="FMIWrapper" name="F"><parameters>
            <parameter name="path" value="broken.fmu" type="string"/></parameters></component></objects>
            </system></hopsanmodelfile>)";
        return loadHmfString(xml, dir.path().string());
    }
    void expectLoadError(const std::string& why)
    {
        LoadedModel loaded = load();
        ASSERT_TRUE(loaded.hasErrors()) << "loaded; expected: " << why;
        EXPECT_NE(loaded.firstError().find(why), std::string::npos) << loaded.firstError();
    }
    // Loads, then fails when the run initialises the FMU, naming `why`.
    void expectRunError(const std::string& why)
    {
        LoadedModel loaded = load();
        ASSERT_FALSE(loaded.hasErrors()) << loaded.firstError();
        Result<Simulation> sim = compile(*loaded.root, {});
        ASSERT_TRUE(sim) << describe(sim.status());
        const Status ran = sim->run();
        ASSERT_FALSE(ran) << "ran; expected: " << why;
        EXPECT_NE(describe(ran).find(why), std::string::npos) << describe(ran);
    }

    TemporaryDirectory dir;
};

TEST_F(FmuImportBroken, MissingLibrary)
{
    writeIntegratorFmu(fmu(), integratorDescription(), "");
    expectRunError("the FMU has no binaries/linux64/integrator.so");
}

TEST_F(FmuImportBroken, LibraryThatIsNotALibrary)
{
    writeZip(fmu(), {{"modelDescription.xml", integratorDescription()},
                     {"binaries/linux64/integrator.so", "not an ELF file"}});
    expectRunError("cannot load the FMU's library");
}

TEST_F(FmuImportBroken, MissingFunction)
{
    writeIntegratorFmu(fmu(), integratorDescription(), TLMHUB_TEST_FMU_LIBRARY_WITHOUT_DO_STEP);
    expectRunError("the FMU's library does not define fmi2DoStep");
}

TEST_F(FmuImportBroken, WrongGuidIsRefusedByTheFmu)
{
    std::string description = integratorDescription();
    description.replace(description.find("{8c4e"), 5, "{0000");
    writeIntegratorFmu(fmu(), description);
    expectRunError("fmi2Instantiate failed");
}

TEST_F(FmuImportBroken, BadModelDescription)
{
    std::string description = integratorDescription();
    description.replace(description.find("causality=\"output\""), 18, "causality=\"parameter\"");
    writeIntegratorFmu(fmu(), description);
    expectLoadError("broken.fmu: modelDescription.xml:");
}

TEST_F(FmuImportBroken, MissingModelDescription)
{
    writeZip(fmu(), {{"binaries/linux64/integrator.so", readFile(TLMHUB_TEST_FMU_LIBRARY)}});
    expectLoadError("broken.fmu has no modelDescription.xml");
}

TEST_F(FmuImportBroken, NotAZip)
{
    writeFile(fmu(), "PK but not really");
    expectLoadError("as a zip archive");
}

TEST_F(FmuImportBroken, HostileArchive)
{
    writeZip(fmu(), {{"modelDescription.xml", integratorDescription()}, {"../escape", "x"}});
    expectLoadError("zip entry '../escape'");
    EXPECT_FALSE(fs::exists(fs::temp_directory_path() / "escape"));
}

TEST_F(FmuImportBroken, NoPathGiven)
{
    const std::string xml = R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="2.20.0"><system name="M">
        <simulationtime stop="0.01" timestep="0.001" start="0"/>
        <objects><component typename="FMIWrapper" name="F"/></objects></system></hopsanmodelfile>)";
    LoadedModel loaded = loadHmfString(xml, dir.path().string());
    ASSERT_FALSE(loaded.hasErrors()) << loaded.firstError();
    Result<Simulation> sim = compile(*loaded.root, {});
    ASSERT_TRUE(sim) << describe(sim.status());
    const Status ran = sim->run();
    EXPECT_NE(describe(ran).find("no FMU loaded"), std::string::npos) << describe(ran);
}

TEST_F(FmuImportBroken, MissingFile)
{
    expectLoadError("no FMU file 'broken.fmu'");
}

} // namespace
} // namespace tlmhub::fmu::test
