// FMU import on a real server: models may use FMUs only from the directory the
// administrator names with --fmu-dir; a model naming one anywhere else, or any FMU on a
// server started without the flag, is refused at submit with a clear error, and the server
// goes on serving. The FMU is the one the server itself exports from FmuGain.hmf (y = 3 u).
#include "ServerHarness.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace tlmhub::test {
namespace {

namespace fs = std::filesystem;

const fs::path kFmuGainImport = fs::path(TLMHUB_SOURCE_DIR) / "tests/server/data/FmuGainImport.hmf";

// FmuGain.hmf exported through the server's own download route, written to `target`.
void downloadFmu(HttpClient& client, const fs::path& target)
{
    const auto id = uploadModel(client, kFmuGain, "FmuGain");
    const auto reply = client.get("/api/v1/models/" + std::to_string(id) + "/fmu");
    ASSERT_EQ(reply.status, 200) << reply.body.substr(0, 300);
    std::ofstream(target, std::ios::binary) << reply.body;
}

// The import model with its FMU path replaced.
std::string importModelNaming(const std::string& fmuPath)
{
    std::string text = readFile(kFmuGainImport);
    const std::string original = R"(value="FmuGain.fmu")";
    text.replace(text.find(original), original.size(), "value=\"" + fmuPath + "\"");
    return text;
}

void expectRefusedNaming(HttpClient& client, const std::string& hmf, const std::string& words)
{
    const auto reply = client.post("/api/v1/jobs", {{"hmf", hmf}});
    EXPECT_GE(reply.status, 400) << reply.body;
    EXPECT_LT(reply.status, 500) << reply.body;
    EXPECT_NE(reply.body.find(words), std::string::npos) << reply.body;
}

} // namespace

TEST(FmuImportServer, ModelsUseFmusFromTheAdministratorsDirectoryOnly)
{
    const fs::path dir = freshTempDir("fmu-import-server");
    const fs::path fmuDir = dir / "fmus";
    fs::create_directories(fmuDir);
    ServerProcess server(dir / "data", {"--fmu-dir", fmuDir.string()});
    createTestUsers(server, {"alice"});
    HttpClient alice = loggedInAs(server, "alice");
    downloadFmu(alice, fmuDir / "FmuGain.fmu");
    fs::copy_file(fmuDir / "FmuGain.fmu", dir / "Outside.fmu");

    const auto submitted = alice.post("/api/v1/jobs", {{"hmf", readFile(kFmuGainImport)}});
    ASSERT_EQ(submitted.status, 201) << submitted.body;
    const std::int64_t job = submitted.json()["id"].get<std::int64_t>();
    const auto done = waitForJobEnd(alice, job);
    ASSERT_EQ(done["state"], "done") << done.dump();
    const auto results =
        alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=json&variables=Gain%23y%23Value").json();
    ASSERT_EQ(results["variables"].size(), 1u) << results.dump().substr(0, 300);
    const auto& y = results["variables"][0]["data"];
    ASSERT_FALSE(y.empty());
    EXPECT_DOUBLE_EQ(y.back().get<double>(), 4.5);   // 3 x 1.5, computed inside the FMU

    // Outside the directory: by a relative path out of it, by an absolute path, or a file
    // that is not there (the same answer, so a model cannot probe the server's files).
    expectRefusedNaming(alice, importModelNaming("../Outside.fmu"), "is not a file in this server's FMU directory");
    expectRefusedNaming(alice, importModelNaming((dir / "Outside.fmu").string()),
                        "is not a file in this server's FMU directory");
    expectRefusedNaming(alice, importModelNaming("Missing.fmu"), "is not a file in this server's FMU directory");
    EXPECT_EQ(alice.get("/api/v1/health").status, 200);
    fs::remove_all(dir);
}

TEST(FmuImportServer, WithoutAnFmuDirectoryNoModelLoadsAnFmu)
{
    const fs::path dir = freshTempDir("fmu-import-none");
    ServerProcess server(dir / "data");
    createTestUsers(server, {"alice"});
    HttpClient alice = loggedInAs(server, "alice");
    fs::create_directories(dir / "fmus");
    downloadFmu(alice, dir / "fmus" / "FmuGain.fmu");
    expectRefusedNaming(alice, importModelNaming((dir / "fmus" / "FmuGain.fmu").string()),
                        "a server loads them only from its --fmu-dir");
    EXPECT_EQ(alice.get("/api/v1/health").status, 200);
    fs::remove_all(dir);
}

} // namespace tlmhub::test

namespace tlmhub::test {
namespace {

// Issue 37 M4: each FMIWrapper unpacks and parses an FMU; a model holds at most
// --max-model-fmus of them (default 64), refused naming the flag before any is loaded.
TEST(FmuImportServer, AModelHoldsAtMostMaxModelFmusWrappers)
{
    const fs::path dir = freshTempDir("fmu-import-limit");
    const fs::path fmuDir = dir / "fmus";
    fs::create_directories(fmuDir);
    ServerProcess server(dir / "data", {"--fmu-dir", fmuDir.string(), "--max-model-fmus", "2"});
    createTestUsers(server, {"alice"});
    HttpClient alice = loggedInAs(server, "alice");
    downloadFmu(alice, fmuDir / "FmuGain.fmu");
    // Two more wrappers beside the model's own: three in all.
    std::string three = readFile(kFmuGainImport);
    const std::string wrapper = R"(<component typename="FMIWrapperQ" name="Gain">)";
    const auto at = three.find(wrapper);
    ASSERT_NE(at, std::string::npos);
    const std::string element = three.substr(at, three.find("</component>", at) + 12 - at);
    std::string more;
    for (const char* name : {"Gain2", "Gain3"}) {
        std::string copy = element;
        copy.replace(copy.find(R"(name="Gain")"), 11, std::string("name=\"") + name + "\"");
        more += copy;
    }
    three.insert(at, more);
    const auto refused = alice.post("/api/v1/jobs", {{"hmf", three}});
    EXPECT_EQ(refused.status, 400) << refused.body;
    EXPECT_NE(refused.body.find("--max-model-fmus"), std::string::npos) << refused.body;
    const auto upload = alice.request(boost::beast::http::verb::post, "/api/v1/models?name=three", three,
                                      "application/xml");
    EXPECT_NE(upload.body.find("--max-model-fmus"), std::string::npos) << upload.body;
    // The model's one wrapper is within the limit.
    EXPECT_EQ(alice.post("/api/v1/jobs", {{"hmf", readFile(kFmuGainImport)}}).status, 201);
}

} // namespace
} // namespace tlmhub::test
