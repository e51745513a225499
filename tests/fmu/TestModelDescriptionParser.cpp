// parseModelDescription: what it reads from a good description, and how it refuses bad ones.
#include "FmuImportTestSupport.h"

#include "fmu/ModelDescription.h"

namespace tlmhub::fmu::test {
namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// Refused as an invalid model, with a message containing `why`.
void expectRefused(const std::string& xml, const std::string& why)
{
    Result<ModelDescription> parsed = parseModelDescription(xml);
    ASSERT_FALSE(parsed) << "accepted; expected: " << why;
    EXPECT_EQ(parsed.status().code(), StatusCode::InvalidModel);
    EXPECT_NE(parsed.status().message().find(why), std::string::npos) << parsed.status().message();
}

const std::string powerPortDescription = R"(<?xml version="1.0"?>
<fmiModelDescription fmiVersion="2.0" modelName="pipe" guid="{1}">
  <CoSimulation modelIdentifier="pipe"/>
  <ModelVariables>
    <ScalarVariable name="P1.c" valueReference="0" causality="input"><Real start="0"/></ScalarVariable>
    <ScalarVariable name="P1.Zc" valueReference="1" causality="input"><Real start="0"/></ScalarVariable>
    <ScalarVariable name="P1.p" valueReference="2" causality="output"><Real/></ScalarVariable>
    <ScalarVariable name="P1.q" valueReference="3" causality="output"><Real/></ScalarVariable>
  </ModelVariables>
  <ModelStructure><Outputs><Unknown index="3"/><Unknown index="4"/></Outputs></ModelStructure>
  <VendorAnnotations><Tool name="tlmhub">
    <PowerPort name="P1" nodeType="NodeHydraulic" kind="C">
      <Input slot="c" variable="P1.c"/><Input slot="Zc" variable="P1.Zc"/>
      <Output slot="p" variable="P1.p"/><Output slot="q" variable="P1.q"/>
    </PowerPort>
  </Tool></VendorAnnotations>
</fmiModelDescription>)";

TEST(ModelDescriptionParser, ReadsTheHandWrittenIntegrator)
{
    Result<ModelDescription> parsed = parseModelDescription(integratorDescription());
    ASSERT_TRUE(parsed) << describe(parsed.status());
    EXPECT_EQ(parsed->modelIdentifier, "integrator");
    EXPECT_EQ(parsed->guid, "{8c4e810f-3df3-4a00-8276-176fa3c9f000}");
    ASSERT_EQ(parsed->variables.size(), 4u);
    EXPECT_EQ(parsed->variables[0].name, "u");
    EXPECT_EQ(parsed->variables[0].causality, Causality::Input);
    EXPECT_EQ(parsed->variables[2].causality, Causality::Parameter);
    EXPECT_EQ(parsed->variables[2].variability, Variability::Fixed);
    EXPECT_EQ(parsed->variables[2].unit, "1/s");
    EXPECT_EQ(parsed->variables[2].start, 1.0);
    EXPECT_EQ(parsed->outputs, std::vector<std::size_t>{2});
    EXPECT_EQ(parsed->stepSize, 0.001);
}

TEST(ModelDescriptionParser, ReadsTlmhubsPowerPortAnnotation)
{
    Result<ModelDescription> parsed = parseModelDescription(powerPortDescription);
    ASSERT_TRUE(parsed) << describe(parsed.status());
    ASSERT_EQ(parsed->powerPorts.size(), 1u);
    const PowerPort& port = parsed->powerPorts[0];
    EXPECT_EQ(port.name, "P1");
    EXPECT_EQ(port.nodeType, "NodeHydraulic");
    EXPECT_EQ(port.kind, 'C');
    EXPECT_EQ(port.inputs, (std::vector<std::pair<std::string, std::string>>{{"c", "P1.c"}, {"Zc", "P1.Zc"}}));
    EXPECT_EQ(port.outputs, (std::vector<std::pair<std::string, std::string>>{{"p", "P1.p"}, {"q", "P1.q"}}));
}

TEST(ModelDescriptionParser, RefusesWhatIsNotAnFmi2CoSimulationDescription)
{
    const std::string good = integratorDescription();
    expectRefused("not xml <", "not XML");
    expectRefused("<model/>", "root element");
    expectRefused(replaced(good, "fmiVersion=\"2.0\"", "fmiVersion=\"3.0\""), "not 2.0");
    expectRefused(replaced(good, "guid=\"{8c4e810f-3df3-4a00-8276-176fa3c9f000}\"", ""), "no guid");
    expectRefused(replaced(good, "<CoSimulation", "<ModelExchange"), "no <CoSimulation>");
    expectRefused(replaced(good, "modelIdentifier=\"integrator\"", "modelIdentifier=\"../../evil\""),
                  "not a C identifier");
    expectRefused(replaced(good, "modelIdentifier=\"integrator\"", ""), "not a C identifier");
}

TEST(ModelDescriptionParser, RefusesBadVariables)
{
    const std::string good = integratorDescription();
    expectRefused(replaced(good, "name=\"y\" valueReference=\"1\"", "name=\"y\" valueReference=\"0\""),
                  "value reference 0 is used twice");
    expectRefused(replaced(good, "name=\"y\" valueReference=\"1\"", "name=\"u\" valueReference=\"1\""),
                  "two variables are named 'u'");
    expectRefused(replaced(good, "causality=\"parameter\" variability=\"fixed\" description=\"gain\"",
                           "causality=\"parameter\" variability=\"continuous\" description=\"gain\""),
                  "is not allowed by FMI 2.0");
    expectRefused(replaced(good, "causality=\"input\" variability=\"continuous\"",
                           "causality=\"input\" variability=\"fixed\""),
                  "is not allowed by FMI 2.0");
    expectRefused(replaced(good, "causality=\"input\"", "causality=\"sideways\""), "unknown causality");
    expectRefused(replaced(good, "valueReference=\"2\"", "valueReference=\"-2\""), "no valid valueReference");
    expectRefused(replaced(good, "<Real start=\"1\" unit=\"1/s\"/>", "<Real start=\"one\"/>"), "not a number");
    expectRefused(replaced(good, "<Real start=\"1\" unit=\"1/s\"/>", ""), "no type element");
}

TEST(ModelDescriptionParser, RefusesOutputsThatAreNotOutputVariables)
{
    const std::string good = integratorDescription();
    expectRefused(replaced(good, "<Unknown index=\"2\"/>", "<Unknown index=\"5\"/>"), "is not a variable's index");
    expectRefused(replaced(good, "<Unknown index=\"2\"/>", "<Unknown index=\"0\"/>"), "is not a variable's index");
    expectRefused(replaced(good, "<Unknown index=\"2\"/>", "<Unknown index=\"1\"/>"), "is not an output");
}

TEST(ModelDescriptionParser, RefusesBadPowerPorts)
{
    expectRefused(replaced(powerPortDescription, "variable=\"P1.c\"", "variable=\"P9.c\""), "no variable named 'P9.c'");
    expectRefused(replaced(powerPortDescription, "variable=\"P1.p\"", "variable=\"P1.c\""), "is not a real output");
    expectRefused(replaced(powerPortDescription, "slot=\"Zc\"", "slot=\"x\""), "'x' is not a variable of NodeHydraulic");
    expectRefused(replaced(powerPortDescription, "nodeType=\"NodeHydraulic\"", "nodeType=\"NodeWarp\""),
                  "unknown power node type");
    expectRefused(replaced(powerPortDescription, "kind=\"C\"", "kind=\"S\""), "kind must be C or Q");
}

TEST(ModelDescriptionParser, RefusesOversizedInput)
{
    std::string huge = integratorDescription();
    huge += std::string((16u << 20) + 1, ' ');
    expectRefused(huge, "larger than 16 MiB");
}

} // namespace
} // namespace tlmhub::fmu::test
