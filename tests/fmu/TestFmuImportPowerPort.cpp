// An FMU with a tlmhub power port (the hand-written pressure source, kind C) imported as a
// Q-type FMIWrapperQ and connected to hydraulic components:
//   Source(FMU) - Volume - LaminarOrifice - TankC
// At steady state the orifice passes Kc (p0 - p_tank) and the source's port holds p0.
#include "FmuImportTestSupport.h"

#include "core/ComponentFactory.h"
#include "core/Simulation.h"
#include "core/System.h"
#include "fmu/FmuLoadPolicy.h"

namespace tlmhub::fmu::test {
namespace {

constexpr double p0 = 5e6, pTank = 1e5, Kc = 1e-11;

class FmuImportPowerPort : public ::testing::Test {
protected:
    void SetUp() override
    {
        setFmuLoadPolicy(FmuLoadPolicy::anywhere());
        writeIntegratorFmu(dir.path() / "source.fmu",
                           readFile(sourceDir() / "tests/fmu/handwritten/pressure_source/modelDescription.xml"),
                           TLMHUB_TEST_FMU_LIBRARY_PRESSURE_SOURCE, "binaries/linux64/pressure_source.so");
        root.modelDirectory = dir.path().string();
    }
    void TearDown() override { setFmuLoadPolicy(FmuLoadPolicy::nowhere()); }
    // Adds a component of `type` named `name` with its parameters set; its definition loaded.
    Component* add(const std::string& type, const std::string& name,
                   const std::vector<std::pair<std::string, std::string>>& parameters = {})
    {
        std::unique_ptr<Component> component = ComponentFactory::instance().create(type);
        EXPECT_TRUE(component) << type;
        if (!component) return nullptr;
        component->setNameRaw(name);
        Component* raw = component.get();
        root.addComponent(std::move(component));
        for (const auto& [parameter, value] : parameters) {
            EXPECT_TRUE(raw->parameters().find(parameter)) << name << "." << parameter;
            if (raw->parameters().find(parameter)) raw->parameters().find(parameter)->value = value;
        }
        const Status loaded = raw->loadExternalDefinition();
        EXPECT_TRUE(loaded) << describe(loaded);
        return raw;
    }

    TemporaryDirectory dir;
    System root;
};

TEST_F(FmuImportPowerPort, KindCFmuIsAQTypePressureSource)
{
    Component* source = add("FMIWrapperQ", "Source", {{"path", "source.fmu"}});
    ASSERT_TRUE(source);
    ASSERT_TRUE(source->parameters().find("p0"));
    source->parameters().find("p0")->value = "5e6";
    EXPECT_EQ(source->kind(), CqsKind::Q);
    ASSERT_TRUE(source->port("P1"));
    EXPECT_EQ(source->port("P1")->nodeType(), NodeType::Hydraulic);
    // Its TLM variables are no signal ports.
    EXPECT_FALSE(source->port("P1_c"));
    add("HydraulicVolume", "Volume");
    add("HydraulicLaminarOrifice", "Orifice");
    add("HydraulicTankC", "Tank");
    ASSERT_TRUE(root.connect("Source", "P1", "Volume", "P1"));
    ASSERT_TRUE(root.connect("Volume", "P2", "Orifice", "P1"));
    ASSERT_TRUE(root.connect("Orifice", "P2", "Tank", "P1"));

    Result<Simulation> sim = compile(root, {0.0, 2.0, 1e-4, 201});
    ASSERT_TRUE(sim) << describe(sim.status());
    ASSERT_TRUE(sim->run());
    const ResultView results = sim->results();
    const auto p = results.data("Source#P1#Pressure");
    const auto q = results.data("Source#P1#Flow");
    ASSERT_TRUE(p && q);
    EXPECT_DOUBLE_EQ(p->back(), p0);
    // Flow leaves the source (positive: out of the component into the node, as Hopsan counts).
    EXPECT_NEAR(q->back(), Kc * (p0 - pTank), 1e-3 * Kc * p0);
}

TEST_F(FmuImportPowerPort, KindCFmuInFMIWrapperNamesTheOtherType)
{
    std::unique_ptr<Component> wrapper = ComponentFactory::instance().create("FMIWrapper");
    Component* raw = wrapper.get();
    root.addComponent(std::move(wrapper));
    raw->parameters().find("path")->value = "source.fmu";
    const Status refused = raw->loadExternalDefinition();
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.message().find("is of kind C; use FMIWrapperQ"), std::string::npos) << refused.message();
}

} // namespace
} // namespace tlmhub::fmu::test
