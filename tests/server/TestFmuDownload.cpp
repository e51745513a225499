// GET /models/{id}/fmu/interface and /models/{id}/fmu through a real server: the interface a
// stored model's FMU has, the FMU itself, and who may fetch them.
#include "ServerHarness.h"
#include "TestFiles.h"

#include <gtest/gtest.h>
#include <zip.h>

#include <set>

namespace tlmhub::test {
namespace {

// The entry names of the zip archive `bytes` (none if it is not one).
std::set<std::string> zipEntries(const std::string& bytes)
{
    std::set<std::string> names;
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
    zip_t* archive = source ? zip_open_from_source(source, ZIP_RDONLY, &error) : nullptr;
    if (archive) {
        for (zip_int64_t i = 0; i < zip_get_num_entries(archive, 0); ++i) names.insert(zip_get_name(archive, i, 0));
        zip_discard(archive);
    } else if (source) {
        zip_source_free(source);
    }
    zip_error_fini(&error);
    return names;
}

class FmuDownload : public ::testing::Test {
protected:
    void SetUp() override
    {
        server = std::make_unique<ServerProcess>(freshTempDir("fmu-download"));
        createTestUsers(*server, {"alice", "bob"});
        alice = std::make_unique<HttpClient>(loggedInAs(*server, "alice"));
        modelPath = "/api/v1/models/" + std::to_string(uploadModel(*alice, kFmuGain, "FmuGain"));
    }

    // The variable named `name` in an interface reply (the test fails without one).
    static nlohmann::json variable(const nlohmann::json& interface, const std::string& name)
    {
        for (const auto& v : interface["variables"])
            if (v["name"] == name) return v;
        ADD_FAILURE() << "no variable " << name << " in " << interface.dump();
        return nlohmann::json::object();
    }

    std::unique_ptr<ServerProcess> server;
    std::unique_ptr<HttpClient> alice;
    std::string modelPath;
};

TEST_F(FmuDownload, InterfaceListsInputsOutputsPowerPortsAndTheStep)
{
    const auto reply = alice->get(modelPath + "/fmu/interface");
    ASSERT_EQ(reply.status, 200) << reply.body;
    const nlohmann::json interface = reply.json();
    EXPECT_EQ(interface["model_identifier"], "FmuGain");
    EXPECT_EQ(interface["default_experiment"]["stop_time"], 2.0);
    EXPECT_EQ(interface["default_experiment"]["step_size"], 0.001);
    const auto u = variable(interface, "u");
    const auto y = variable(interface, "y");
    const auto step = variable(interface, "tlmhub.timestep");
    EXPECT_EQ(u["causality"], "input");
    EXPECT_EQ(u["variability"], "continuous");
    EXPECT_EQ(u["type"], "Real");
    EXPECT_EQ(y["causality"], "output");
    EXPECT_EQ(step["causality"], "parameter");
    EXPECT_EQ(step["start"], 0.001);
    // Value references count from 0: inputs, then outputs, then parameters with the step last.
    const auto& variables = interface["variables"];
    for (std::size_t i = 0; i < variables.size(); ++i) EXPECT_EQ(variables[i]["value_reference"], i);
    EXPECT_LT(u["value_reference"], y["value_reference"]);
    EXPECT_EQ(step["value_reference"], variables.size() - 1);
    // Each C-type hydraulic port takes the wave variable and impedance and gives the others.
    ASSERT_EQ(interface["power_ports"].size(), 2u);
    const auto& pa = interface["power_ports"][0];
    EXPECT_EQ(pa["name"], "PA");
    EXPECT_EQ(pa["node_type"], "NodeHydraulic");
    EXPECT_EQ(pa["kind"], "C");
    EXPECT_EQ(pa["inputs"], nlohmann::json::parse(R"([{"node_variable": "c", "variable": "PA.c"},
                                                      {"node_variable": "Zc", "variable": "PA.Zc"}])"));
    EXPECT_EQ(variable(interface, "PA.c")["causality"], "input");
    EXPECT_EQ(variable(interface, "PA.p")["causality"], "output");
}

TEST_F(FmuDownload, InterfaceOffersTheNamedParametersUnderTheChosenIdentifier)
{
    const auto reply = alice->get(modelPath + "/fmu/interface?parameters=Gain.k&identifier=MyGain");
    ASSERT_EQ(reply.status, 200) << reply.body;
    EXPECT_EQ(reply.json()["model_identifier"], "MyGain");
    const auto k = variable(reply.json(), "Gain.k");
    EXPECT_EQ(k["causality"], "parameter");
    EXPECT_EQ(k["variability"], "fixed");
    EXPECT_EQ(k["start"], 3.0);
}

TEST_F(FmuDownload, AModelWithoutAValidInterfaceIsUnprocessable)
{
    const auto unknown = alice->get(modelPath + "/fmu/interface?parameters=Gain.nope");
    EXPECT_EQ(unknown.status, 422) << unknown.body;
    EXPECT_NE(unknown.json()["error"]["message"].get<std::string>().find("Gain.nope"), std::string::npos) << unknown.body;
    const auto identifier = alice->get(modelPath + "/fmu/interface?identifier=not%20an%20identifier");
    EXPECT_EQ(identifier.status, 422) << identifier.body;
    EXPECT_EQ(identifier.json()["error"]["code"], "bad_request");
}

TEST_F(FmuDownload, OnlyThoseWhoMayReadTheModelSeeItsInterface)
{
    HttpClient anonymous(server->port());
    EXPECT_EQ(anonymous.get(modelPath + "/fmu/interface").status, 401);
    HttpClient bob = loggedInAs(*server, "bob");
    EXPECT_EQ(bob.get(modelPath + "/fmu/interface").status, 404);
}

TEST_F(FmuDownload, TheFmuIsAZipWithDescriptionBinaryAndModel)
{
    const auto reply = alice->get(modelPath + "/fmu?parameters=Gain.k&identifier=MyGain");
    ASSERT_EQ(reply.status, 200) << reply.body;
    EXPECT_EQ(reply.headers.at("Content-Type"), "application/zip");
    EXPECT_NE(reply.headers.at("Content-Disposition").find("filename=\"MyGain.fmu\""), std::string::npos);
    const std::set<std::string> entries = zipEntries(reply.body);
    EXPECT_TRUE(entries.count("modelDescription.xml")) << reply.body.size() << " bytes";
    EXPECT_TRUE(entries.count("binaries/linux64/MyGain.so"));
    EXPECT_TRUE(entries.count("resources/model.hmf"));
    // What is refused for the interface is refused for the download.
    EXPECT_EQ(alice->get(modelPath + "/fmu?parameters=Gain.nope").status, 422);
}

TEST_F(FmuDownload, OnlyThoseWhoMayReadTheModelDownloadItsFmu)
{
    HttpClient anonymous(server->port());
    EXPECT_EQ(anonymous.get(modelPath + "/fmu").status, 401);
    HttpClient bob = loggedInAs(*server, "bob");
    EXPECT_EQ(bob.get(modelPath + "/fmu").status, 404);
    // A browser's download goes through a link signed for one target and user.
    const auto link = alice->post("/api/v1/auth/download-link", {{"target", modelPath + "/fmu"}});
    ASSERT_EQ(link.status, 200) << link.body;
    const auto download = anonymous.get(link.json()["url"].get<std::string>());
    EXPECT_EQ(download.status, 200);
    EXPECT_TRUE(zipEntries(download.body).count("modelDescription.xml"));
}

// A server without the runtime library says so and goes on serving the rest.
TEST(FmuDownloadWithoutRuntime, AnswersUnavailable)
{
    ServerProcess server(freshTempDir("fmu-no-runtime"), {}, {"env", "TLMHUB_FMU_RUNTIME=/nonexistent/libtlmhub-fmu-runtime.so"});
    createTestUsers(server, {"alice"});
    HttpClient alice = loggedInAs(server, "alice");
    const std::string modelPath = "/api/v1/models/" + std::to_string(uploadModel(alice, kFmuGain, "FmuGain"));
    const auto reply = alice.get(modelPath + "/fmu");
    EXPECT_EQ(reply.status, 503);
    EXPECT_EQ(reply.json()["error"]["code"], "unavailable");
    EXPECT_NE(reply.json()["error"]["message"].get<std::string>().find("TLMHUB_FMU_RUNTIME"), std::string::npos) << reply.body;
    EXPECT_EQ(alice.get(modelPath + "/fmu/interface").status, 200);
}

} // namespace
} // namespace tlmhub::test
