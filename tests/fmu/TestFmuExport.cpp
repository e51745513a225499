// The interface rules (fmu/ModelInterface.h), the description writer and the resource
// location of the runtime, without a built FMU (TestFmuChecker.cpp checks the whole FMU).
#include "core/Model.h"
#include "core/hmf/HmfLoader.h"
#include "fmu/FmuExport.h"
#include "fmu/Guid.h"
#include "fmu/ModelInterface.h"
#include "fmu/runtime/ResourceLocation.h"

#include <gtest/gtest.h>
#include <pugixml.hpp>

namespace tlmhub::fmu {
namespace {

Model loadInterfacesModel()
{
    LoadedModel loaded = loadHmfFile(std::string(TLMHUB_SOURCE_DIR) + "/tests/fmu/models/Interfaces.hmf");
    EXPECT_FALSE(loaded.hasErrors()) << loaded.firstError();
    return Model(std::move(loaded.root));
}

std::vector<std::string> namesOf(const ModelInterface& modelInterface)
{
    std::vector<std::string> names;
    for (const ScalarVariable& v : modelInterface.description.variables)
        names.push_back(v.name);
    return names;
}

TEST(FmuInterface, InputsOutputsParametersTimestepInThatOrder)
{
    Model model = loadInterfacesModel();
    Result<ModelInterface> described = describeInterface(model.root(), {{"Orifice.Kc"}, {}});
    ASSERT_TRUE(described) << describe(described.status());
    EXPECT_EQ(namesOf(*described), (std::vector<std::string>{"In", "P1.c", "P1.Zc", "Out", "P1.q", "P1.p", "gain",
                                                             "Orifice.Kc", "tlmhub.timestep"}));
    const ModelDescription& d = described->description;
    for (std::size_t i = 0; i < d.variables.size(); ++i)
        EXPECT_EQ(d.variables[i].valueReference, i);
    EXPECT_EQ(d.outputs, (std::vector<std::size_t>{4, 5, 6}));
    EXPECT_EQ(d.modelIdentifier, "Interfaces");
    EXPECT_EQ(d.stopTime, 0.5);
    EXPECT_EQ(d.stepSize, 0.001);
    EXPECT_EQ(d.variables[6].start, 2.0);
    EXPECT_EQ(d.variables[8].start, 0.001);
    EXPECT_EQ(described->bindings[7].kind, VariableBinding::Kind::Parameter);
    EXPECT_EQ(described->bindings[7].parameterPath, "Orifice.Kc");
    EXPECT_EQ(described->bindings[1].component, "P1");
    EXPECT_EQ(described->bindings[1].slot, NodeHydraulic::WaveVariable);
    ASSERT_EQ(d.powerPorts.size(), 1u);
    const PowerPort& port = d.powerPorts[0];
    EXPECT_EQ(port.kind, 'C');
    EXPECT_EQ(port.inputs, (std::vector<std::pair<std::string, std::string>>{{"c", "P1.c"}, {"Zc", "P1.Zc"}}));
    EXPECT_EQ(port.outputs, (std::vector<std::pair<std::string, std::string>>{{"q", "P1.q"}, {"p", "P1.p"}}));

    // The inputs start where the initialised model's nodes are: c copied from p's start.
    ASSERT_TRUE(takeInputStartsFromInitialisation(*described, model));
    EXPECT_EQ(described->description.variables[1].start, 1e5);
}

TEST(FmuInterface, AQTypePortTakesEffortAndFlow)
{
    LoadedModel loaded = loadHmfString(R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="2.20.0">
        <system name="Mech"><objects><component name="M" typename="MechanicInterfaceQ"/></objects></system>
        </hopsanmodelfile>)",
                                       ".", "mech.hmf");
    ASSERT_FALSE(loaded.hasErrors()) << loaded.firstError();
    Result<ModelInterface> described = describeInterface(*loaded.root, {{}, "mech_fmu"});
    ASSERT_TRUE(described) << describe(described.status());
    EXPECT_EQ(described->description.modelIdentifier, "mech_fmu");
    const PowerPort& port = described->description.powerPorts.at(0);
    EXPECT_EQ(port.kind, 'Q');
    EXPECT_EQ(port.nodeType, "NodeMechanic");
    for (const auto& [slot, variable] : port.outputs)
        EXPECT_TRUE(slot == "c" || slot == "Zc") << slot;
    EXPECT_EQ(port.outputs.size(), 2u);
    EXPECT_GE(port.inputs.size(), 2u);
}

TEST(FmuInterface, RefusesWhatCannotBeAnFmuVariable)
{
    Model model = loadInterfacesModel();
    Result<ModelInterface> twice = describeInterface(model.root(), {{"Orifice.Kc", "Orifice.Kc"}, {}});
    ASSERT_FALSE(twice);
    EXPECT_NE(twice.status().message().find("Orifice.Kc"), std::string::npos);

    Result<ModelInterface> nothing = describeInterface(model.root(), {{"Nope.x"}, {}});
    ASSERT_FALSE(nothing);
    EXPECT_NE(describe(nothing.status()).find("Nope"), std::string::npos) << describe(nothing.status());

    Result<ModelInterface> expression = describeInterface(model.root(), {{"Gain.k"}, {}});
    ASSERT_FALSE(expression);
    EXPECT_EQ(expression.status().code(), StatusCode::InvalidParameter);

    Result<ModelInterface> identifier = describeInterface(model.root(), {{}, "1 model"});
    ASSERT_FALSE(identifier);
    EXPECT_EQ(identifier.status().code(), StatusCode::InvalidSettings);
}

TEST(FmuInterface, ModelIdentifierIsACIdentifierOfTheName)
{
    LoadedModel loaded = loadHmfString(R"(<hopsanmodelfile hmfversion="0.4" hopsancoreversion="2.20.0">
        <system name="2nd model"/></hopsanmodelfile>)",
                                       ".", "name.hmf");
    ASSERT_TRUE(loaded.root) << loaded.firstError();
    loaded.root->setNameRaw("2nd model-x");
    Result<ModelInterface> described = describeInterface(*loaded.root);
    ASSERT_TRUE(described) << describe(described.status());
    EXPECT_EQ(described->description.modelIdentifier, "_2nd_model_x");
}

TEST(FmuDescription, WritesTheVendorAnnotationBeforeTheVariables)
{
    Model model = loadInterfacesModel();
    Result<ModelInterface> described = describeInterface(model.root());
    ASSERT_TRUE(described);
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(writeModelDescription(described->description).c_str()));
    pugi::xml_node root = doc.child("fmiModelDescription");
    std::vector<std::string> order;
    for (pugi::xml_node child : root.children())
        order.push_back(child.name());
    EXPECT_EQ(order, (std::vector<std::string>{"CoSimulation", "UnitDefinitions", "DefaultExperiment",
                                               "VendorAnnotations", "ModelVariables", "ModelStructure"}));
    pugi::xml_node out = root.child("ModelVariables").find_child_by_attribute("ScalarVariable", "name", "Out");
    EXPECT_FALSE(out.child("Real").attribute("start")) << "a calculated output has no start";
}

TEST(FmuGuid, DependsOnTheModelAndTheOfferedParameters)
{
    const std::string a = guidOfModel("<model/>", {});
    EXPECT_EQ(a, guidOfModel("<model/>", {}));
    EXPECT_NE(a, guidOfModel("<model />", {}));
    EXPECT_NE(a, guidOfModel("<model/>", {"M.m"}));
    EXPECT_EQ(a.size(), 38u);
    EXPECT_EQ(a.front(), '{');
    EXPECT_EQ(a[9], '-');
}

TEST(FmuResourceLocation, FileUrisOnly)
{
    EXPECT_EQ(directoryOfFileUri("file:///tmp/My%20Model/resources/"), "/tmp/My Model/resources");
    EXPECT_EQ(directoryOfFileUri("file:/tmp/a"), "/tmp/a");
    EXPECT_EQ(directoryOfFileUri("file://localhost/tmp/a"), "/tmp/a");
    EXPECT_EQ(directoryOfFileUri("file://server/tmp/a"), std::nullopt);
    EXPECT_EQ(directoryOfFileUri("http://x/tmp"), std::nullopt);
    EXPECT_EQ(directoryOfFileUri("file:///tmp/%2"), std::nullopt);
    EXPECT_EQ(directoryOfFileUri("file:///tmp/%zz"), std::nullopt);
}

TEST(FmuExport, RefusesAModelThatDoesNotLoad)
{
    Result<std::string> zip = exportFmu("<not a model", "x.hmf", {}, "/nonexistent/runtime.so");
    ASSERT_FALSE(zip);
    EXPECT_EQ(zip.status().code(), StatusCode::InvalidModel);
}

} // namespace
} // namespace tlmhub::fmu
