// .hmf load -> save -> load gives the same model: same results bit for bit, and the GUI
// data the core does not interpret is kept.
#include "TestHelpers.h"

#include "core/hmf/HmfLoader.h"
#include "core/hmf/HmfSaver.h"

#include <filesystem>
#include <fstream>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

std::vector<std::vector<double>> simulateAll(System& root)
{
    const std::optional<Simulation> sim = runToStop(compile(root));
    if (!sim) return {};
    return loggedColumns(sim->results());
}

std::size_t countOf(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// "Comp.port: A.pa B.pb ..." for every multiport of the root, its sub-ports in order.
std::string multiportOrder(const System& root)
{
    std::string out;
    for (const Component* c : root.componentsInOrder())
        for (const Port* p : c->ports()) {
            if (!p->isMultiport()) continue;
            out += c->name() + "." + p->name() + ":";
            for (const auto& sub : p->subPorts)
                for (const Port* q : sub->connectedPorts) out += " " + q->component()->name() + "." + q->name();
            out += "\n";
        }
    return out;
}

void roundTrip(const std::string& relPath)
{
    const std::string path = sharedDir() + "/hopsan-models/" + relPath;
    ASSERT_TRUE(std::filesystem::exists(path)) << "shared model missing: " << path;
    LoadedModel first = loadHmfFile(path);
    ASSERT_FALSE(first.hasErrors()) << first.firstError();
    const std::string saved = saveHmfString(*first.root);
    LoadedModel second = loadHmfString(saved, first.root->modelDirectory, "saved copy");
    ASSERT_FALSE(second.hasErrors()) << second.firstError();
    // Saving the reloaded model gives the same text (a fixed point).
    EXPECT_EQ(saveHmfString(*second.root), saved);
    // GUI data survives, including every connection's line, whichever way round the file
    // listed the connection.
    EXPECT_NE(saved.find("<hopsangui>"), std::string::npos);
    std::ifstream original(path);
    const std::string text((std::istreambuf_iterator<char>(original)), std::istreambuf_iterator<char>());
    EXPECT_EQ(countOf(saved, "<coordinates>"), countOf(text, "<coordinates>"));
    EXPECT_GT(countOf(saved, "<coordinates>"), 0u);
    const auto a = simulateAll(*first.root);
    const auto b = simulateAll(*second.root);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GT(a.size(), 1u);
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << "column " << i;
}

} // namespace

TEST(HmfRoundTrip, PositionServo) { roundTrip("Example Models/Position Servo.hmf"); }

TEST(HmfRoundTrip, SubSystemExampleWithNestedSystems) { roundTrip("Example Models/Sub System Example.hmf"); }

TEST(HmfRoundTrip, OwnExampleModel)
{
    LoadedModel first = loadHmfFile(std::string(TLMHUB_SOURCE_DIR) + "/examples/pressure-build-up.hmf");
    ASSERT_FALSE(first.hasErrors()) << first.firstError();
    const std::string saved = saveHmfString(*first.root);
    LoadedModel second = loadHmfString(saved, first.root->modelDirectory);
    ASSERT_FALSE(second.hasErrors()) << second.firstError();
    EXPECT_EQ(simulateAll(*first.root), simulateAll(*second.root));
    // System parameters and expressions are kept as strings.
    EXPECT_NE(saved.find("relief_pressure"), std::string::npos);
}

TEST(HmfLoader, BrokenInputGivesClearErrors)
{
    LoadedModel m = loadHmfString("<hopsanmodelfile><system", ".", "broken.hmf");
    EXPECT_TRUE(m.hasErrors());
    EXPECT_NE(m.firstError().find("broken.hmf"), std::string::npos);
    EXPECT_NE(m.firstError().find("broken XML"), std::string::npos);

    m = loadHmfString(R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="2.20.0"><system name="S">
        <objects><component name="X" typename="NoSuchType"/></objects></system></hopsanmodelfile>)",
                      ".", "unknown.hmf");
    EXPECT_TRUE(m.hasErrors());
    EXPECT_NE(m.firstError().find("NoSuchType"), std::string::npos) << m.firstError();

    m = loadHmfString(R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="2.20.0"><system name="S">
        <objects><component name="V1" typename="HydraulicVolume"/><component name="V2" typename="HydraulicVolume"/></objects>
        <connections><connect startcomponent="V1" startport="P1" endcomponent="V2" endport="P1"/></connections>
        </system></hopsanmodelfile>)",
                      ".", "illegal.hmf");
    EXPECT_TRUE(m.hasErrors());
    EXPECT_NE(m.firstError().find("V1.P1"), std::string::npos) << m.firstError();

    m = loadHmfFile("/nonexistent/model.hmf");
    EXPECT_TRUE(m.hasErrors());
    EXPECT_NE(m.firstError().find("/nonexistent/model.hmf"), std::string::npos);
}

TEST(HmfLoader, OldParameterNamesAreRewrittenForOldFiles)
{
    // A 0.6.x development build below r5500: '::' becomes '#', plain names retry '#Value'.
    LoadedModel m = loadHmfString(R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="0.6.x_r5148"><system name="S">
        <objects><component name="G" typename="SignalGain"><parameters>
          <parameter name="k::Value" value="3"/></parameters></component>
          <component name="O" typename="HydraulicLaminarOrifice"><parameters>
          <parameter name="Kc" value="2e-9"/></parameters></component></objects></system></hopsanmodelfile>)",
                                  ".", "old.hmf");
    ASSERT_FALSE(m.hasErrors()) << m.firstError();
    EXPECT_EQ(m.root->component("G")->parameters().find("k#Value")->value, "3");
    EXPECT_EQ(m.root->component("O")->parameters().find("Kc#Value")->value, "2e-9");
}

// The saver listed connections from whichever end it came to first, so a multiport whose
// connections a file lists in another order got its sub-ports reordered on reload, and the
// saved model computed something else (this one and other shared models).
TEST(HmfRoundTrip, KeepsEachMultiportsOrderAndResults)
{
    LoadedModel loaded = loadHmfFile(sharedDir() + "/hopsan-models/Example Models/Load Sensing System.hmf");
    ASSERT_TRUE(loaded.root) << loaded.firstError();
    LoadedModel reloaded = loadHmfString(saveHmfString(*loaded.root), loaded.root->modelDirectory, "saved");
    ASSERT_TRUE(reloaded.root) << reloaded.firstError();
    EXPECT_EQ(multiportOrder(*reloaded.root), multiportOrder(*loaded.root));
    const auto fromFile = simulateAll(*loaded.root);
    ASSERT_GT(fromFile.size(), 1u);
    EXPECT_TRUE(simulateAll(*reloaded.root) == fromFile);
}
