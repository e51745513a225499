// Hostile model files: nesting and size are bounded while loading, with an error that names
// the limit, instead of a stack overflow or unbounded memory.
#include "core/FileAccess.h"
#include "core/hmf/HmfLoader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace tlmhub;

namespace {

// A root system holding `levels` subsystems, each inside the one before.
std::string nestedSubsystems(std::size_t levels)
{
    std::string open, close;
    for (std::size_t i = 0; i < levels; ++i) {
        open += "<system typename=\"Subsystem\" name=\"S" + std::to_string(i) + "\"><objects>";
        close += "</objects></system>";
    }
    return "<hopsanmodelfile hopsancoreversion=\"2.20.0\"><system name=\"root\"><objects>" + open +
           close + "</objects></system></hopsanmodelfile>";
}

std::string manyGains(std::size_t count)
{
    std::string objects;
    for (std::size_t i = 0; i < count; ++i)
        objects += "<component typename=\"SignalGain\" name=\"G" + std::to_string(i) + "\"/>";
    return "<hopsanmodelfile><system name=\"root\"><objects>" + objects +
           "</objects></system></hopsanmodelfile>";
}

} // namespace

TEST(HmfLimits, TenThousandNestedSubsystemsAreRefusedNamingTheDepth)
{
    const LoadedModel loaded = loadHmfString(nestedSubsystems(10000), "", "deep.hmf");
    EXPECT_FALSE(loaded.root);
    EXPECT_NE(loaded.firstError().find("nested more than 512 levels"), std::string::npos)
        << loaded.firstError();
}

TEST(HmfLimits, SubsystemDepthLimitIsExact)
{
    LoadLimits limits;
    limits.maxSubsystemDepth = 5;
    EXPECT_TRUE(loadHmfString(nestedSubsystems(5), "", "ok.hmf", limits).root);
    const LoadedModel deeper = loadHmfString(nestedSubsystems(6), "", "deep.hmf", limits);
    EXPECT_FALSE(deeper.root);
    EXPECT_NE(deeper.firstError().find("'S5' is nested 6 levels deep; the limit is 5"), std::string::npos)
        << deeper.firstError();
    // The default bound applies without any limits given.
    EXPECT_TRUE(loadHmfString(nestedSubsystems(64), "", "ok.hmf").root);
    EXPECT_FALSE(loadHmfString(nestedSubsystems(65), "", "deep.hmf").root);
}

TEST(HmfLimits, DeeplyNestedPreservedXmlIsRefusedBeforeLoading)
{
    std::string gui;
    for (int i = 0; i < 100000; ++i) gui += "<a>";
    for (int i = 0; i < 100000; ++i) gui += "</a>";
    const LoadedModel loaded = loadHmfString(
        "<hopsanmodelfile><system name=\"root\"><hopsangui>" + gui + "</hopsangui></system></hopsanmodelfile>",
        "", "gui.hmf");
    EXPECT_FALSE(loaded.root);
    EXPECT_NE(loaded.firstError().find("gui.hmf: XML elements are nested more than"), std::string::npos)
        << loaded.firstError();
}

TEST(HmfLimits, ComponentCountLimit)
{
    LoadLimits limits;
    limits.maxComponents = 100;
    EXPECT_TRUE(loadHmfString(manyGains(100), "", "ok.hmf", limits).root);
    const LoadedModel tooMany = loadHmfString(manyGains(101), "", "big.hmf", limits);
    EXPECT_FALSE(tooMany.root);
    EXPECT_NE(tooMany.firstError().find("more than 100 components and subsystems"), std::string::npos)
        << tooMany.firstError();
    EXPECT_TRUE(loadHmfString(manyGains(101), "", "ok.hmf").root) << "no count limit by default";
}

TEST(HmfLimits, AnExternalSubsystemThatIncludesItselfEndsAtTheDepthLimit)
{
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "tlmhub-self-including";
    fs::create_directories(dir);
    std::ofstream(dir / "self.hmf")
        << "<hopsanmodelfile><system name=\"root\"><objects>"
           "<system typename=\"Subsystem\" name=\"again\" external_path=\"self.hmf\"/>"
           "</objects></system></hopsanmodelfile>";
    setModelFileAccess(true);
    const LoadedModel loaded = loadHmfFile((dir / "self.hmf").string());
    EXPECT_FALSE(loaded.root);
    EXPECT_NE(loaded.firstError().find("the limit is 0"), std::string::npos) << loaded.firstError();
    fs::remove_all(dir);
}

TEST(HmfLimits, RefusalsEndWithTheCallersHintOnRaisingTheLimit)
{
    LoadLimits limits;
    limits.maxSubsystemDepth = 2;
    limits.depthHint = " (raise with --depth)";
    limits.maxComponents = 3;
    limits.componentsHint = " (raise with --components)";
    const std::string deep = loadHmfString(nestedSubsystems(3), "", "deep.hmf", limits).firstError();
    EXPECT_NE(deep.find("the limit is 2 (raise with --depth)"), std::string::npos) << deep;
    const std::string many = loadHmfString(manyGains(4), "", "many.hmf", limits).firstError();
    EXPECT_NE(many.find("the limit here (raise with --components)"), std::string::npos) << many;
}
