// The exported FMU checked as an importer would see it: `tlmhub-cli fmu` writes it, the test
// unzips it, checks modelDescription.xml against FMI 2.0's rules, loads the binary with
// dlopen and co-simulates it, comparing each communication point with `tlmhub-cli run`.
// The model (tests/fmu/models/Interfaces.hmf) has a signal input, a signal output and a
// hydraulic C-type power port. Left at their starts (the values the model's own
// initialisation gives their nodes), the inputs make a plain run of the model the reference;
// for the signal input set to 1.5, the reference is the model with a SignalConstant of 1.5
// in place of the input interface.
#include "fmu/Fmi2.h"

#include <gtest/gtest.h>
#include <pugixml.hpp>
#include <zip.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kModel = std::string(TLMHUB_SOURCE_DIR) + "/tests/fmu/models/Interfaces.hmf";

// Runs a shell command; its standard output, or fails the test.
std::string runCommand(const std::string& command)
{
    std::string output;
    std::FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) {
        ADD_FAILURE() << "cannot run " << command;
        return output;
    }
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        output.append(buffer, n);
    EXPECT_EQ(pclose(pipe), 0) << command << "\n" << output;
    return output;
}

std::string quoted(const std::string& text)
{
    return "'" + text + "'";
}

void unzipInto(const fs::path& archive, const fs::path& directory)
{
    int error = 0;
    zip_t* zip = zip_open(archive.c_str(), ZIP_RDONLY, &error);
    ASSERT_NE(zip, nullptr) << "cannot open " << archive;
    for (zip_int64_t i = 0; i < zip_get_num_entries(zip, 0); ++i) {
        zip_stat_t stat;
        ASSERT_EQ(zip_stat_index(zip, i, 0, &stat), 0);
        std::string bytes(stat.size, '\0');
        zip_file_t* file = zip_fopen_index(zip, i, 0);
        ASSERT_NE(file, nullptr);
        ASSERT_EQ(zip_fread(file, bytes.data(), bytes.size()), static_cast<zip_int64_t>(bytes.size()));
        zip_fclose(file);
        const fs::path target = directory / stat.name;
        fs::create_directories(target.parent_path());
        std::ofstream(target, std::ios::binary) << bytes;
    }
    zip_close(zip);
}

// `tlmhub-cli run --csv` of a model: column name -> one value per step from the start.
std::map<std::string, std::vector<double>> referenceRun(const fs::path& directory, const std::string& extraArgs,
                                                        const std::string& model = kModel)
{
    const fs::path csv = directory / "reference.csv";
    runCommand(quoted(TLMHUB_CLI) + " run " + quoted(model) + " --samples 501 " + extraArgs + " --csv " +
               quoted(csv.string()));
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    for (std::istringstream header(line); std::getline(header, line, ',');)
        names.push_back(line);
    std::map<std::string, std::vector<double>> columns;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        for (const std::string& name : names) {
            std::string cell;
            std::getline(row, cell, ',');
            columns[name].push_back(std::stod(cell));
        }
    }
    return columns;
}

// The FMU's functions, looked up by name as an importer does.
struct Fmi2Api {
#define TLMHUB_DECLARE_POINTER(name) name##TYPE* name = nullptr;
    TLMHUB_FMI2_COSIMULATION_FUNCTIONS(TLMHUB_DECLARE_POINTER)
#undef TLMHUB_DECLARE_POINTER
};

std::vector<std::string> gLog;

void logger(fmi2ComponentEnvironment, fmi2String instance, fmi2Status status, fmi2String category,
            fmi2String message, ...)
{
    char text[2048];
    va_list args;
    va_start(args, message);
    std::vsnprintf(text, sizeof text, message, args);
    va_end(args);
    gLog.push_back(std::string(instance) + " [" + category + "] " + std::to_string(status) + ": " + text);
}

const fmi2CallbackFunctions kCallbacks{logger, nullptr, nullptr, nullptr, nullptr};

class FmuChecker : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        // A space in the path: the resource location must be percent-encoded.
        sDirectory = fs::temp_directory_path() / ("tlmhub fmu checker-" + std::to_string(::getpid()));
        fs::create_directories(sDirectory);
        const fs::path fmu = sDirectory / "Interfaces.fmu";
        runCommand(quoted(TLMHUB_CLI) + " fmu " + quoted(kModel) + " -o " + quoted(fmu.string()) +
                   " --parameter Orifice.Kc");
        unzipInto(fmu, sDirectory / "unzipped");
        std::ifstream in(sDirectory / "unzipped/modelDescription.xml");
        std::ostringstream xml;
        xml << in.rdbuf();
        sXml = xml.str();
        sLibrary = dlopen((sDirectory / "unzipped/binaries/linux64/Interfaces.so").c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!sLibrary)
            return;
#define TLMHUB_LOOK_UP(name) sApi.name = reinterpret_cast<name##TYPE*>(dlsym(sLibrary, #name));
        TLMHUB_FMI2_COSIMULATION_FUNCTIONS(TLMHUB_LOOK_UP)
#undef TLMHUB_LOOK_UP
    }
    static void TearDownTestSuite()
    {
        if (sLibrary)
            dlclose(sLibrary);
        fs::remove_all(sDirectory);
    }
    void SetUp() override
    {
        ASSERT_NE(sLibrary, nullptr) << dlerror();
        gLog.clear();
    }

    static std::string guid()
    {
        pugi::xml_document doc;
        doc.load_string(sXml.c_str());
        return doc.child("fmiModelDescription").attribute("guid").value();
    }
    static std::string resourceUri()
    {
        std::string uri = "file://";
        for (char ch : (sDirectory / "unzipped/resources").string())
            uri += ch == ' ' ? std::string("%20") : std::string(1, ch);
        return uri;
    }
    static fmi2Component instantiate(const std::string& guidText)
    {
        return sApi.fmi2Instantiate("checker", fmi2CoSimulation, guidText.c_str(), resourceUri().c_str(),
                                    &kCallbacks, fmi2False, fmi2False);
    }
    static std::string log()
    {
        std::string text;
        for (const std::string& line : gLog)
            text += line + "\n";
        return text;
    }

    // Value references of the model (Interfaces.hmf; the ModelDescription test checks them).
    enum : fmi2ValueReference { In = 0, P1c, P1Zc, Out, P1q, P1p, Gain, OrificeKc, Timestep };

    // Co-simulates from 0 to 0.5 s with one model step per communication step and compares
    // the outputs with the reference run at every point.
    void expectSameAsRun(fmi2Component c, const std::map<std::string, std::vector<double>>& reference)
    {
        const std::pair<fmi2ValueReference, const char*> outputs[] = {
            {Out, "Out#in#Value"}, {P1q, "P1#P1#Flow"}, {P1p, "P1#P1#Pressure"}};
        const double h = 0.001;
        for (int k = 0; k <= 500; ++k) {
            if (k > 0) {
                ASSERT_EQ(sApi.fmi2DoStep(c, (k - 1) * h, h, fmi2True), fmi2OK) << "step " << k << "\n" << log();
            }
            for (const auto& [vr, column] : outputs) {
                fmi2Real value = 0;
                ASSERT_EQ(sApi.fmi2GetReal(c, &vr, 1, &value), fmi2OK);
                ASSERT_EQ(value, reference.at(column).at(k)) << column << " at step " << k;
            }
        }
    }

    static fs::path sDirectory;
    static std::string sXml;
    static void* sLibrary;
    static Fmi2Api sApi;
};

fs::path FmuChecker::sDirectory;
std::string FmuChecker::sXml;
void* FmuChecker::sLibrary = nullptr;
Fmi2Api FmuChecker::sApi;

// FMI 2.0 table of legal causality/variability pairs (section 2.2.7).
bool legalCombination(const std::string& causality, const std::string& variability)
{
    static const std::set<std::pair<std::string, std::string>> legal = {
        {"parameter", "fixed"},        {"parameter", "tunable"},       {"calculatedParameter", "fixed"},
        {"calculatedParameter", "tunable"}, {"input", "discrete"},    {"input", "continuous"},
        {"output", "constant"},        {"output", "discrete"},         {"output", "continuous"},
        {"local", "constant"},         {"local", "fixed"},             {"local", "tunable"},
        {"local", "discrete"},         {"local", "continuous"},        {"independent", "continuous"}};
    return legal.count({causality, variability}) != 0;
}

TEST_F(FmuChecker, ModelDescriptionFollowsFmi2)
{
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(sXml.c_str()));
    pugi::xml_node root = doc.child("fmiModelDescription");
    ASSERT_TRUE(root);
    EXPECT_STREQ(root.attribute("fmiVersion").value(), "2.0");
    EXPECT_STREQ(root.attribute("modelName").value(), "Interfaces");
    EXPECT_EQ(guid().size(), 38u);
    EXPECT_EQ(std::string(root.attribute("generationTool").value()).rfind("tlmhub ", 0), 0u);
    EXPECT_STREQ(root.attribute("variableNamingConvention").value(), "flat");
    EXPECT_STREQ(root.child("CoSimulation").attribute("modelIdentifier").value(), "Interfaces");
    EXPECT_FALSE(root.child("ModelExchange"));
    EXPECT_DOUBLE_EQ(root.child("DefaultExperiment").attribute("stepSize").as_double(), 0.001);

    std::set<std::string> units;
    for (pugi::xml_node unit : root.child("UnitDefinitions").children("Unit"))
        units.insert(unit.attribute("name").value());

    std::vector<pugi::xml_node> variables;
    std::set<std::string> names;
    std::set<unsigned> references;
    std::set<std::size_t> outputIndices;
    for (pugi::xml_node variable : root.child("ModelVariables").children("ScalarVariable")) {
        variables.push_back(variable);
        const std::string name = variable.attribute("name").value();
        const std::string causality = variable.attribute("causality").as_string("local");
        const std::string variability = variable.attribute("variability").as_string("continuous");
        const std::string initial = variable.attribute("initial").value();
        pugi::xml_node real = variable.child("Real");
        SCOPED_TRACE(name);
        EXPECT_TRUE(names.insert(name).second) << "duplicate name";
        EXPECT_TRUE(references.insert(variable.attribute("valueReference").as_uint()).second) << "duplicate vr";
        EXPECT_TRUE(legalCombination(causality, variability));
        ASSERT_TRUE(real) << "tlmhub's FMU variables are real";
        if (real.attribute("unit")) {
            EXPECT_TRUE(units.count(real.attribute("unit").value())) << "undeclared unit";
        }
        // Start: required for inputs and parameters (whose initial is exact), forbidden for
        // calculated outputs.
        if (causality == "input" || causality == "parameter") {
            EXPECT_TRUE(real.attribute("start"));
            EXPECT_TRUE(initial.empty() || (causality == "parameter" && initial == "exact"));
        }
        if (causality == "output") {
            EXPECT_EQ(bool(real.attribute("start")), initial == "exact" || initial == "approx");
            outputIndices.insert(variables.size());
        }
    }
    EXPECT_EQ(names, (std::set<std::string>{"In", "P1.c", "P1.Zc", "Out", "P1.q", "P1.p", "gain", "Orifice.Kc",
                                            "tlmhub.timestep"}));
    for (unsigned vr = In; vr <= Timestep; ++vr)
        EXPECT_EQ(variables.at(vr).attribute("valueReference").as_uint(), vr);

    std::set<std::size_t> listed;
    for (pugi::xml_node unknown : root.child("ModelStructure").child("Outputs").children("Unknown")) {
        const std::size_t index = unknown.attribute("index").as_ullong();
        EXPECT_GE(index, 1u);
        EXPECT_LE(index, variables.size());
        EXPECT_TRUE(listed.insert(index).second);
    }
    EXPECT_EQ(listed, outputIndices) << "ModelStructure/Outputs must list exactly the outputs";
    for (pugi::xml_node unknown : root.child("ModelStructure").child("InitialUnknowns").children("Unknown"))
        EXPECT_TRUE(outputIndices.count(unknown.attribute("index").as_ullong()));

    pugi::xml_node port = root.child("VendorAnnotations").find_child_by_attribute("Tool", "name", "tlmhub")
                              .child("PowerPort");
    EXPECT_STREQ(port.attribute("name").value(), "P1");
    EXPECT_STREQ(port.attribute("nodeType").value(), "NodeHydraulic");
    EXPECT_STREQ(port.attribute("kind").value(), "C");
    EXPECT_STREQ(port.child("Input").attribute("variable").value(), "P1.c");
}

TEST_F(FmuChecker, ExportsEveryFmi2FunctionAndNothingElse)
{
#define TLMHUB_EXPECT_FOUND(name) EXPECT_NE(reinterpret_cast<void*>(sApi.name), nullptr) << #name;
    TLMHUB_FMI2_COSIMULATION_FUNCTIONS(TLMHUB_EXPECT_FOUND)
#undef TLMHUB_EXPECT_FOUND
    std::set<std::string> expected;
#define TLMHUB_NAME(name) expected.insert(#name);
    TLMHUB_FMI2_COSIMULATION_FUNCTIONS(TLMHUB_NAME)
#undef TLMHUB_NAME
    const std::string symbols = runCommand(
        "nm -D --defined-only " + quoted((sDirectory / "unzipped/binaries/linux64/Interfaces.so").string()) +
        " | awk '{print $3}'");
    std::set<std::string> exported;
    std::istringstream lines(symbols);
    for (std::string name; std::getline(lines, name);)
        if (!name.empty())
            exported.insert(name);
    EXPECT_EQ(exported, expected);
    EXPECT_STREQ(sApi.fmi2GetVersion(), "2.0");
    EXPECT_STREQ(sApi.fmi2GetTypesPlatform(), "default");
}

TEST_F(FmuChecker, CoSimulationGivesTheRunsValuesAtEveryStep)
{
    const auto reference = referenceRun(sDirectory, "");
    fmi2Component c = instantiate(guid());
    ASSERT_NE(c, nullptr) << log();
    ASSERT_EQ(sApi.fmi2SetupExperiment(c, fmi2False, 0, 0.0, fmi2True, 0.5), fmi2OK);
    ASSERT_EQ(sApi.fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(sApi.fmi2ExitInitializationMode(c), fmi2OK) << log();
    expectSameAsRun(c, reference);
    fmi2Real time = -1;
    EXPECT_EQ(sApi.fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &time), fmi2OK);
    EXPECT_NEAR(time, 0.5, 1e-12);
    EXPECT_EQ(sApi.fmi2DoStep(c, 0.5, 0.001, fmi2True), fmi2Error) << "past the stop time";
    EXPECT_EQ(sApi.fmi2Terminate(c), fmi2OK);
    fmi2Boolean terminated = fmi2False;
    EXPECT_EQ(sApi.fmi2GetBooleanStatus(c, fmi2Terminated, &terminated), fmi2OK);
    EXPECT_EQ(terminated, fmi2True);

    // Reset: the same run again.
    ASSERT_EQ(sApi.fmi2Reset(c), fmi2OK);
    ASSERT_EQ(sApi.fmi2SetupExperiment(c, fmi2False, 0, 0.0, fmi2False, 0.0), fmi2OK);
    ASSERT_EQ(sApi.fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(sApi.fmi2ExitInitializationMode(c), fmi2OK) << log();
    expectSameAsRun(c, reference);
    EXPECT_EQ(sApi.fmi2Terminate(c), fmi2OK);
    sApi.fmi2FreeInstance(c);
}

TEST_F(FmuChecker, ParameterSetBeforeInitialisationActsAsInARunWithIt)
{
    const auto reference = referenceRun(sDirectory, "--param gain=3 --param Orifice.Kc=2e-11");
    fmi2Component c = instantiate(guid());
    ASSERT_NE(c, nullptr) << log();
    ASSERT_EQ(sApi.fmi2SetupExperiment(c, fmi2False, 0, 0.0, fmi2True, 0.5), fmi2OK);
    const fmi2ValueReference parameters[] = {Gain, OrificeKc};
    const fmi2Real values[] = {3.0, 2e-11};
    ASSERT_EQ(sApi.fmi2SetReal(c, parameters, 2, values), fmi2OK);
    ASSERT_EQ(sApi.fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(sApi.fmi2ExitInitializationMode(c), fmi2OK) << log();
    fmi2Real read[2] = {};
    EXPECT_EQ(sApi.fmi2GetReal(c, parameters, 2, read), fmi2OK);
    EXPECT_EQ(read[0], 3.0);
    expectSameAsRun(c, reference);
    EXPECT_EQ(sApi.fmi2SetReal(c, parameters, 1, values), fmi2Error) << "a fixed parameter after initialisation";
    EXPECT_NE(log().find("fixed"), std::string::npos) << log();
    sApi.fmi2FreeInstance(c);
}

// The reference for an input set during initialisation: the model with a constant source in
// place of the input interface (same name, so the same columns).
std::string modelWithConstantInput(const fs::path& directory, double value)
{
    std::ifstream in(kModel);
    std::ostringstream text;
    text << in.rdbuf();
    std::string hmf = text.str();
    auto replace = [&](const std::string& from, const std::string& to) {
        const std::size_t at = hmf.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        hmf.replace(at, from.size(), to);
    };
    replace(R"(<component typename="SignalInputInterface" name="In"/>)",
            R"(<component typename="SignalConstant" name="In"><parameters><parameter name="y#Value" value=")" +
                std::to_string(value) + R"(" type="double"/></parameters></component>)");
    replace(R"(startcomponent="In" startport="out")", R"(startcomponent="In" startport="y")");
    const fs::path path = directory / "ConstantInput.hmf";
    std::ofstream(path) << hmf;
    return path.string();
}

TEST_F(FmuChecker, AnInputSetInInitialisationActsAsAConstantSource)
{
    const auto reference = referenceRun(sDirectory, "", modelWithConstantInput(sDirectory, 1.5));
    fmi2Component c = instantiate(guid());
    ASSERT_NE(c, nullptr) << log();
    ASSERT_EQ(sApi.fmi2SetupExperiment(c, fmi2False, 0, 0.0, fmi2True, 0.5), fmi2OK);
    ASSERT_EQ(sApi.fmi2EnterInitializationMode(c), fmi2OK);
    const fmi2ValueReference input = In;
    const fmi2Real value = 1.5;
    ASSERT_EQ(sApi.fmi2SetReal(c, &input, 1, &value), fmi2OK);
    ASSERT_EQ(sApi.fmi2ExitInitializationMode(c), fmi2OK) << log();
    expectSameAsRun(c, reference);
    sApi.fmi2FreeInstance(c);
}

TEST_F(FmuChecker, InputsApplyFromTheNextStep)
{
    fmi2Component c = instantiate(guid());
    ASSERT_NE(c, nullptr) << log();
    ASSERT_EQ(sApi.fmi2SetupExperiment(c, fmi2False, 0, 0.0, fmi2True, 0.5), fmi2OK);
    ASSERT_EQ(sApi.fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(sApi.fmi2ExitInitializationMode(c), fmi2OK) << log();
    // The wave variable and impedance of the port's other side: p = c + Zc q at the port.
    const fmi2ValueReference inputs[] = {P1c, P1Zc};
    const fmi2Real values[] = {5e6, 1e9};
    ASSERT_EQ(sApi.fmi2SetReal(c, inputs, 2, values), fmi2OK);
    ASSERT_EQ(sApi.fmi2DoStep(c, 0.0, 0.01, fmi2True), fmi2OK) << log();
    fmi2Real q = 0, p = 0;
    const fmi2ValueReference flow = P1q, pressure = P1p;
    ASSERT_EQ(sApi.fmi2GetReal(c, &flow, 1, &q), fmi2OK);
    ASSERT_EQ(sApi.fmi2GetReal(c, &pressure, 1, &p), fmi2OK);
    EXPECT_GT(q, 0.0) << "flow from the 10 MPa source into the 5 MPa side";
    EXPECT_NEAR(p, 5e6 + 1e9 * q, 1e-6 * p);
    // 0.0015 s is not a whole number of 1 ms steps.
    EXPECT_EQ(sApi.fmi2DoStep(c, 0.01, 0.0015, fmi2True), fmi2Error);
    EXPECT_NE(log().find("whole number"), std::string::npos) << log();
    sApi.fmi2FreeInstance(c);
}

TEST_F(FmuChecker, RefusesAnotherModelsGuid)
{
    EXPECT_EQ(instantiate("{00000000-0000-0000-0000-000000000000}"), nullptr);
    EXPECT_NE(log().find("GUID"), std::string::npos) << log();
    EXPECT_EQ(sApi.fmi2Instantiate("x", fmi2ModelExchange, guid().c_str(), resourceUri().c_str(), &kCallbacks,
                                   fmi2False, fmi2False),
              nullptr);
}

TEST_F(FmuChecker, UnsupportedFunctionsReturnError)
{
    fmi2Component c = instantiate(guid());
    ASSERT_NE(c, nullptr) << log();
    fmi2FMUstate state = nullptr;
    EXPECT_EQ(sApi.fmi2GetFMUstate(c, &state), fmi2Error);
    EXPECT_EQ(sApi.fmi2SetFMUstate(c, state), fmi2Error);
    EXPECT_EQ(sApi.fmi2FreeFMUstate(c, &state), fmi2Error);
    EXPECT_EQ(sApi.fmi2GetDirectionalDerivative(c, nullptr, 0, nullptr, 0, nullptr, nullptr), fmi2Error);
    EXPECT_EQ(sApi.fmi2SetRealInputDerivatives(c, nullptr, 0, nullptr, nullptr), fmi2Error);
    EXPECT_EQ(sApi.fmi2CancelStep(c), fmi2Error);
    EXPECT_NE(log().find("not supported"), std::string::npos) << log();
    const fmi2ValueReference vr = 0;
    fmi2Integer integer = 0;
    EXPECT_EQ(sApi.fmi2GetInteger(c, &vr, 0, &integer), fmi2OK);
    EXPECT_EQ(sApi.fmi2GetInteger(c, &vr, 1, &integer), fmi2Error);
    fmi2Status status;
    EXPECT_EQ(sApi.fmi2GetStatus(c, fmi2PendingStatus, &status), fmi2Discard);
    const fmi2ValueReference output = Out;
    fmi2Real value = 0;
    EXPECT_EQ(sApi.fmi2GetReal(c, &output, 1, &value), fmi2Error) << "an output before initialisation";
    EXPECT_EQ(sApi.fmi2DoStep(c, 0.0, 0.001, fmi2True), fmi2Error) << "a step before initialisation";
    sApi.fmi2FreeInstance(c);
}

} // namespace
