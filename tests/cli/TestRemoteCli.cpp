// tlmhub-cli remote against a real tlmhub-server on loopback: the binary's exit status and
// output, the files it writes, over http and through a TLS proxy.
#include "ChildProcess.h"
#include "server/ServerHarness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <thread>

namespace tlmhub::test {
namespace {

const std::string kModel = std::string(TLMHUB_SOURCE_DIR) + "/examples/pressure-build-up.hmf";

class RemoteCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        mDir = freshTempDir("cli-remote");
        mServer = std::make_unique<ServerProcess>(mDir / "data");
        mAdmin = std::make_unique<HttpClient>(mServer->port());
        mToken = mAdmin->login("admin", kAdminPassword);
        mUrl = "http://127.0.0.1:" + std::to_string(mServer->port());
    }

    // The environment of a logged-in user: TLMHUB_URL and TLMHUB_TOKEN (a login session's
    // token, which the server takes like an API token), and a configuration directory of
    // this test's own.
    std::map<std::string, std::string> loggedIn() const
    {
        auto env = noCredentials();
        env["TLMHUB_URL"] = mUrl;
        env["TLMHUB_TOKEN"] = mToken;
        return env;
    }
    std::map<std::string, std::string> noCredentials() const
    {
        return {{"HOME", (mDir / "home").string()}, {"XDG_CONFIG_HOME", (mDir / "config").string()}};
    }
    std::filesystem::path credentialsFile() const { return mDir / "config" / "tlmhub" / "credentials"; }

    // Runs `remote ARGS...` with `env`.
    static CliResult remote(std::vector<std::string> args, const std::map<std::string, std::string>& env,
                            const std::string& input = "")
    {
        args.insert(args.begin(), "remote");
        return runCli(args, env, input);
    }

    // The job id in run's summary ("ok: MODEL: job 12 (model 3), ...").
    static std::string jobId(const CliResult& run)
    {
        std::smatch m;
        if (!std::regex_search(run.out, m, std::regex("job ([0-9]+) "))) ADD_FAILURE() << "no job id in: " << run.out;
        return m.size() > 1 ? m[1].str() : "0";
    }

    void writeCredentialsFile(const std::string& url, const std::string& token) const
    {
        std::filesystem::create_directories(credentialsFile().parent_path());
        std::ofstream(credentialsFile()) << nlohmann::json{{"url", url}, {"token", token}}.dump();
    }

    std::filesystem::path mDir;
    std::unique_ptr<ServerProcess> mServer;
    std::unique_ptr<HttpClient> mAdmin;
    std::string mToken;
    std::string mUrl;
};

TEST_F(RemoteCli, RunWritesTheServersResultCsvWhichEqualsALocalRun)
{
    const auto remoteCsv = mDir / "remote.csv", localCsv = mDir / "local.csv";
    const CliResult run = remote({"run", kModel, "--csv", remoteCsv.string()}, loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("ok: " + kModel + ": job "), std::string::npos) << run.out;
    const HttpReply server = mAdmin->get("/api/v1/jobs/" + jobId(run) + "/results?format=csv");
    ASSERT_EQ(server.status, 200);
    EXPECT_EQ(readFile(remoteCsv), server.body);

    const CliResult local = runCli({"run", kModel, "--csv", localCsv.string()});
    ASSERT_EQ(local.exitCode, 0) << local.err;
    EXPECT_EQ(readFile(remoteCsv), readFile(localCsv));
}

TEST_F(RemoteCli, RunPassesParametersAndTimesToTheJob)
{
    const CliResult run = remote({"run", kModel, "--param", "pump_flow=2e-4", "--stop", "1"}, loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("t=[0, 1]"), std::string::npos) << run.out;
    const nlohmann::json job = mAdmin->get("/api/v1/jobs/" + jobId(run)).json();
    EXPECT_EQ(job["state"], "done");
    EXPECT_EQ(job["settings"]["stop"], 1.0);
}

TEST_F(RemoteCli, PipedProgressIsPlainLinesEachTenPerCent)
{
    const CliResult run = remote({"run", kModel}, loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find('\r'), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("job " + jobId(run) + ": 100 % done\n"), std::string::npos) << run.err;
    // Every line is "job N: P % STATE" with P a multiple of 10, each P once at most.
    std::istringstream lines(run.err);
    std::set<std::string> seen;
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        ASSERT_TRUE(std::regex_match(line, m, std::regex("job [0-9]+: ([0-9]*0) % [a-z]+"))) << line;
        EXPECT_TRUE(seen.insert(m[1].str()).second) << run.err;
    }
}

TEST_F(RemoteCli, OnATerminalProgressIsABarRedrawnInPlace)
{
    // script(1) gives the command a terminal (stdout and stderr both go to it).
    const CliResult run =
        runProgram({"script", "-qec", "'" + std::string(TLMHUB_CLI_BIN) + "' remote run '" + kModel + "'", "/dev/null"},
                   loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.out;
    EXPECT_TRUE(std::regex_search(run.out, std::regex("\rjob [0-9]+ \\[#{30}\\] 100 % done *\r\n"))) << run.out;
    EXPECT_EQ(run.out.find(": 100 %"), std::string::npos) << run.out;   // no plain lines
}

TEST_F(RemoteCli, JobsListsTheCallersJobs)
{
    const CliResult run = remote({"run", kModel}, loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const CliResult jobs = remote({"jobs"}, loggedIn());
    ASSERT_EQ(jobs.exitCode, 0) << jobs.err;
    EXPECT_EQ(jobs.out.rfind("      ID  STATE", 0), 0u) << jobs.out;
    EXPECT_TRUE(std::regex_search(jobs.out, std::regex("\n +" + jobId(run) + "  done +100 %"))) << jobs.out;
}

// A cancelled study is listed as such, and `studies resume` queues it to run the runs it lacks.
TEST_F(RemoteCli, StudiesListsTheCallersStudiesAndResumesACancelledOne)
{
    const auto submitted = mAdmin->post("/api/v1/studies", {{"kind", "sweep"}, {"hmf", readFile(kModel)},
                                                            {"sweep", {{"parameters", {{"pump_flow", {{"from", 1e-4}, {"to", 2e-4}, {"steps", 300}}}}}}}});
    ASSERT_EQ(submitted.status, 201) << submitted.body;
    const std::string id = std::to_string(submitted.json()["id"].get<long long>());
    const std::string path = "/api/v1/studies/" + id;
    ASSERT_LT(mAdmin->request(boost::beast::http::verb::delete_, path).status, 300);
    nlohmann::json study;
    for (int i = 0; i < 3000 && (study = mAdmin->get(path).json())["state"] != "cancelled"; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_EQ(study["state"], "cancelled") << study.dump();

    const CliResult listed = remote({"studies", "list"}, loggedIn());
    ASSERT_EQ(listed.exitCode, 0) << listed.err;
    EXPECT_EQ(listed.out.rfind("      ID  KIND         STATE", 0), 0u) << listed.out;
    EXPECT_TRUE(std::regex_search(listed.out, std::regex("\n +" + id + "  sweep +cancelled "))) << listed.out;

    const CliResult resumed = remote({"studies", "resume", id}, loggedIn());
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_TRUE(std::regex_search(resumed.out, std::regex("^study " + id + " resumed: [0-9]+ of 300 runs stored"))) << resumed.out;
    for (int i = 0; i < 6000 && (study = mAdmin->get(path).json())["state"] != "done"; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(study["state"], "done") << study.dump();
    EXPECT_EQ(study["runs_done"], 300);

    const CliResult again = remote({"studies", "resume", id}, loggedIn());
    EXPECT_EQ(again.exitCode, 1);
    EXPECT_NE(again.err.find("error: conflict: the study is done"), std::string::npos) << again.err;
    EXPECT_EQ(remote({"studies", "resume", "x"}, loggedIn()).exitCode, 2);
    EXPECT_EQ(remote({"studies", "pause", id}, loggedIn()).exitCode, 2);
}

// A sweep takes what a run takes (--param, --stop): its one run's final pressure is the one a
// `remote run` with the same parameters and stop time ends with. A random sweep samples its
// range --samples times, the same values for the same --seed.
TEST_F(RemoteCli, StudiesTakeParametersTimesAndRandomSamples)
{
    const std::string pressure = "ChamberPressure#P1#Pressure";
    const CliResult sweep = remote({"sweep", kModel, "--vary", "pump_flow=1.5e-4", "--mode", "list", "--param",
                                    "relief_pressure=5e6", "--stop", "1", "--output", pressure + ":final", "--csv", "-"},
                                   loggedIn());
    ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
    const std::string row = sweep.out.substr(sweep.out.find('\n') + 1);
    const double swept = std::strtod(row.substr(row.rfind(',') + 1).c_str(), nullptr);
    const CliResult run = remote({"run", kModel, "--param", "pump_flow=1.5e-4", "--param", "relief_pressure=5e6",
                                  "--stop", "1", "--csv", "-"},
                                 loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // The run's last row, in the column of the pressure.
    const auto cellsOf = [](const std::string& text) {
        std::vector<std::string> cells;
        std::istringstream in(text);
        for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
        return cells;
    };
    const std::string header = run.out.substr(0, run.out.find('\n'));
    const std::string trimmed = run.out.substr(0, run.out.size() - 1);
    const std::vector<std::string> names = cellsOf(header), last = cellsOf(trimmed.substr(trimmed.rfind('\n') + 1));
    const auto column = std::find(names.begin(), names.end(), pressure) - names.begin();
    ASSERT_LT(static_cast<std::size_t>(column), last.size()) << header;
    EXPECT_NEAR(std::strtod(last[0].c_str(), nullptr), 1.0, 1e-9) << "the run stops at 1 s";
    EXPECT_EQ(swept, std::strtod(last[column].c_str(), nullptr)) << "sweep row " << row;

    const std::vector<std::string> random = {"sweep", kModel, "--mode", "random", "--samples", "5", "--seed", "3",
                                             "--vary", "pump_flow=1e-4:2e-4", "--stop", "0.1", "--csv", "-"};
    const CliResult first = remote(random, loggedIn()), second = remote(random, loggedIn());
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_EQ(std::count(first.out.begin(), first.out.end(), '\n'), 6) << first.out;
    EXPECT_EQ(first.out, second.out) << "the same seed samples the same values";
    std::istringstream rows(first.out);
    std::string line;
    std::getline(rows, line);
    while (std::getline(rows, line)) {
        const double value = std::strtod(line.substr(line.rfind(',') + 1).c_str(), nullptr);
        EXPECT_TRUE(value >= 1e-4 && value <= 2e-4) << line;
    }
    for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
             {"sweep", kModel, "--mode", "random", "--vary", "pump_flow=1:2"},
             {"sweep", kModel, "--vary", "pump_flow=1,2", "--samples", "3"},
             {"sweep", kModel, "--vary", "pump_flow=1,2", "--stop", "x"},
             {"optimise", kModel, "--bound", "pump_flow=1:2", "--objective", "final:Volume#P1#p", "--tolerance", "0"},
             {"optimise", kModel, "--bound", "pump_flow=1:2", "--objective", "final:Volume#P1#p", "--max-evaluations", "x"}})
        EXPECT_EQ(remote(bad, loggedIn()).exitCode, 2) << bad.back();
}

// studies show, cancel and results act on one study by id, as the REST API does.
TEST_F(RemoteCli, StudiesShowCancelAndFetchTheResultsOfOneStudy)
{
    const auto submitted = mAdmin->post("/api/v1/studies", {{"kind", "sweep"}, {"hmf", readFile(kModel)}, {"stop", 2},
                                                            {"sweep", {{"parameters", {{"pump_flow", {{"from", 1e-4}, {"to", 2e-4}, {"steps", 2000}}}}}}}});
    ASSERT_EQ(submitted.status, 201) << submitted.body;
    const std::string id = std::to_string(submitted.json()["id"].get<long long>());
    const CliResult cancel = remote({"studies", "cancel", id}, loggedIn());
    ASSERT_EQ(cancel.exitCode, 0) << cancel.err;
    EXPECT_TRUE(std::regex_match(cancel.out, std::regex("studies/" + id + " (cancelled|cancelling)\n"))) << cancel.out;
    nlohmann::json study;
    for (int i = 0; i < 3000 && (study = mAdmin->get("/api/v1/studies/" + id).json())["state"] != "cancelled"; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_EQ(study["state"], "cancelled");

    const CliResult again = remote({"studies", "cancel", id}, loggedIn());
    EXPECT_EQ(again.exitCode, 1);
    EXPECT_NE(again.err.find("the study is cancelled"), std::string::npos) << again.err;
    EXPECT_EQ(mAdmin->get("/api/v1/studies/" + id).status, 200) << "a second cancel must not delete it";

    const CliResult show = remote({"studies", "show", id}, loggedIn());
    ASSERT_EQ(show.exitCode, 0) << show.err;
    EXPECT_EQ(nlohmann::json::parse(show.out)["state"], "cancelled") << show.out;
    const CliResult results = remote({"studies", "results", id}, loggedIn());
    ASSERT_EQ(results.exitCode, 0) << results.err;
    EXPECT_EQ(results.out, mAdmin->get("/api/v1/studies/" + id + "/results?format=csv").body);
    EXPECT_EQ(remote({"studies", "show"}, loggedIn()).exitCode, 2);
    EXPECT_EQ(remote({"studies", "show", "999999"}, loggedIn()).exitCode, 1);
}

// remote sensitivity: the study's table, and its bands as the server's CSV.
TEST_F(RemoteCli, SensitivityWritesItsTableAndBands)
{
    const auto table = mDir / "sensitivity.csv", bands = mDir / "bands.csv";
    const CliResult sensitivity =
        remote({"sensitivity", kModel, "--runs", "8", "--distribution", "pump_flow=uniform:1e-4:2e-4", "--seed", "2",
                "--output", "ChamberPressure#P1#Pressure:final", "--stop", "0.5", "--csv", table.string(), "--bands",
                bands.string()},
               loggedIn());
    ASSERT_EQ(sensitivity.exitCode, 0) << sensitivity.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(sensitivity.out, m, std::regex("^ok: .*: study ([0-9]+), 8 runs, 0 failed, table ")))
        << sensitivity.out;
    const std::string csv = readFile(table);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9) << csv;
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "run,ok,pump_flow,ChamberPressure#P1#Pressure:final");
    EXPECT_EQ(readFile(bands), mAdmin->get("/api/v1/studies/" + m[1].str() + "/bands?format=csv").body);
    for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
             {"sensitivity", kModel, "--distribution", "pump_flow=uniform:1:2", "--output", "V#P1#p:final"},
             {"sensitivity", kModel, "--runs", "8", "--output", "V#P1#p:final"},
             {"sensitivity", kModel, "--runs", "8", "--distribution", "pump_flow=gamma:1:2", "--output", "V#P1#p:final"},
             {"sensitivity", kModel, "--runs", "8", "--distribution", "pump_flow=normal:1:2"}})
        EXPECT_EQ(remote(bad, loggedIn()).exitCode, 2) << bad[3];
}

// A stored model is named by its id: nothing is uploaded again, and the run is the same.
TEST_F(RemoteCli, AModelIdRunsTheStoredModelWithoutAnotherUpload)
{
    const CliResult first = remote({"run", kModel, "--csv", "-"}, loggedIn());
    ASSERT_EQ(first.exitCode, 0) << first.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(first.err, m, std::regex("\\(model ([0-9]+)\\)"))) << first.err;
    const std::string model = m[1].str();
    const auto models = mAdmin->get("/api/v1/models").json().size();

    const CliResult byId = remote({"run", model, "--csv", "-"}, loggedIn());
    ASSERT_EQ(byId.exitCode, 0) << byId.err;
    EXPECT_NE(byId.err.find("(model " + model + ")"), std::string::npos) << byId.err;
    EXPECT_EQ(byId.out, first.out);
    const CliResult swept = remote({"sweep", model, "--vary", "pump_flow=1e-4,2e-4", "--csv", "-"}, loggedIn());
    ASSERT_EQ(swept.exitCode, 0) << swept.err;
    EXPECT_EQ(mAdmin->get("/api/v1/models").json().size(), models) << "a model id uploads nothing";

    const CliResult missing = remote({"run", "999999"}, loggedIn());
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("not_found"), std::string::npos) << missing.err;
}

// A file run again runs the model its first run stored: the same text is not stored twice.
// A changed file is stored anew. (The file is the example's with a comment added: the
// example itself is stored already, and a run of it uses that one.)
TEST_F(RemoteCli, AFileRunAgainRunsTheModelItsFirstRunStored)
{
    const auto modelOf = [](const CliResult& run) {
        std::smatch m;
        const std::string printed = run.out + run.err;
        if (!std::regex_search(printed, m, std::regex("\\(model ([0-9]+)\\)"))) ADD_FAILURE() << printed;
        return m.size() > 1 ? m[1].str() : std::string();
    };
    const auto file = mDir / "pressure-build-up.hmf";
    std::ofstream(file) << readFile(kModel) << "\n<!-- mine -->\n";
    const auto before = mAdmin->get("/api/v1/models").json().size();
    const CliResult first = remote({"run", file.string()}, loggedIn());
    ASSERT_EQ(first.exitCode, 0) << first.err;
    const CliResult again = remote({"run", file.string()}, loggedIn());
    ASSERT_EQ(again.exitCode, 0) << again.err;
    const CliResult swept = remote({"sweep", file.string(), "--vary", "pump_flow=1e-4,2e-4"}, loggedIn());
    ASSERT_EQ(swept.exitCode, 0) << swept.err;
    EXPECT_EQ(modelOf(again), modelOf(first));
    EXPECT_EQ(mAdmin->get("/api/v1/models").json().size(), before + 1) << "stored once";

    std::ofstream(file, std::ios::app) << "<!-- changed -->\n";
    const CliResult edited = remote({"run", file.string()}, loggedIn());
    ASSERT_EQ(edited.exitCode, 0) << edited.err;
    EXPECT_NE(modelOf(edited), modelOf(first));
    EXPECT_EQ(mAdmin->get("/api/v1/models").json().size(), before + 2) << "another text: stored";
}

TEST_F(RemoteCli, ResultsWritesAJobsCsvWhole)
{
    const CliResult run = remote({"run", kModel}, loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string id = jobId(run);
    const auto file = mDir / "results.csv";
    const CliResult toFile = remote({"results", id, "--csv", file.string()}, loggedIn());
    ASSERT_EQ(toFile.exitCode, 0) << toFile.err;
    EXPECT_EQ(readFile(file), mAdmin->get("/api/v1/jobs/" + id + "/results?format=csv").body);

    const std::string header = mAdmin->get("/api/v1/jobs/" + id + "/results?format=csv").body;
    const std::string firstVariable = header.substr(5, header.find_first_of(",\n", 5) - 5);
    const CliResult some = remote({"results", id, "--variables", firstVariable}, loggedIn());
    ASSERT_EQ(some.exitCode, 0) << some.err;
    EXPECT_EQ(some.out, mAdmin->get("/api/v1/jobs/" + id + "/results?format=csv&variables=" + firstVariable).body);
    EXPECT_EQ(some.out.substr(0, some.out.find('\n')), "time," + firstVariable);
}

TEST_F(RemoteCli, TheEnvironmentOverridesTheCredentialsFile)
{
    const std::string closed = "http://127.0.0.1:" + std::to_string(closedPort());
    writeCredentialsFile(closed, "tlmh_not-a-token");
    auto env = noCredentials();
    CliResult jobs = remote({"jobs"}, env);
    EXPECT_EQ(jobs.exitCode, 1);
    EXPECT_NE(jobs.err.find("error: cannot connect to " + closed.substr(7) + ": Connection refused"), std::string::npos)
        << jobs.err;

    env["TLMHUB_URL"] = mUrl;   // the file's token, the environment's server
    jobs = remote({"jobs"}, env);
    EXPECT_EQ(jobs.exitCode, 1);
    EXPECT_NE(jobs.err.find("error: unauthorized: "), std::string::npos) << jobs.err;

    env["TLMHUB_TOKEN"] = mToken;
    jobs = remote({"jobs"}, env);
    EXPECT_EQ(jobs.exitCode, 0) << jobs.err;

    writeCredentialsFile(mUrl, mToken);   // the file alone
    jobs = remote({"jobs"}, noCredentials());
    EXPECT_EQ(jobs.exitCode, 0) << jobs.err;
}

TEST_F(RemoteCli, WithoutCredentialsSaysHowToLogIn)
{
    const CliResult jobs = remote({"jobs"}, noCredentials());
    EXPECT_EQ(jobs.exitCode, 1);
    EXPECT_NE(jobs.err.find("error: not logged in: run 'tlmhub-cli remote login URL'"), std::string::npos) << jobs.err;
}

TEST_F(RemoteCli, UnauthorizedAndNotFoundPrintTheServersError)
{
    auto env = loggedIn();
    env["TLMHUB_TOKEN"] = "tlmh_AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA";
    const CliResult refused = remote({"run", kModel}, env);
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_EQ(refused.err.rfind("error: unauthorized: ", 0), 0u) << refused.err;
    EXPECT_NE(refused.err.find("tlmhub-cli remote login URL"), std::string::npos) << refused.err;

    const CliResult missing = remote({"results", "999999"}, loggedIn());
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_EQ(missing.err.rfind("error: not_found: ", 0), 0u) << missing.err;
    EXPECT_EQ(missing.out, "");
}

TEST_F(RemoteCli, AJobOverALimitIsRefusedWithTheServersCode)
{
    const CliResult run = remote({"run", kModel, "--step", "1e-9"}, loggedIn());
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.err.rfind("error: limit_exceeded: ", 0), 0u) << run.err;
}

TEST_F(RemoteCli, AFailedJobPrintsItsErrorAndExitsOne)
{
    ServerProcess strict(mDir / "strict", {"--max-wall-seconds", "0.05"});
    HttpClient admin(strict.port());
    auto env = loggedIn();
    env["TLMHUB_URL"] = "http://127.0.0.1:" + std::to_string(strict.port());
    env["TLMHUB_TOKEN"] = admin.login("admin", kAdminPassword);
    const auto csv = mDir / "never.csv";
    const CliResult run = remote({"run", kModel, "--stop", "200", "--csv", csv.string()}, env);   // 2e6 steps
    EXPECT_EQ(run.exitCode, 1);
    const std::regex failed("\nerror: job [0-9]+ failed: wall time limit \\(0.05 s\\) exceeded\n$");
    EXPECT_TRUE(std::regex_search(run.err, failed)) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(std::filesystem::exists(csv));
}

TEST_F(RemoteCli, UsageErrorsExitTwoWithTheUsage)
{
    const std::vector<std::vector<std::string>> cases = {
        {},
        {"bogus"},
        {"login"},
        {"login", "ftp://example.org"},
        {"run"},
        {"run", kModel, "--stop", "soon"},
        {"run", kModel, "--no-such-option", "1"},
        {"run", kModel, "--csv"},
        {"run", kModel, "--param", "pump_flow"},
        {"sweep", kModel},
        {"sweep", kModel, "--vary", "pump_flow=1:2"},
        {"sweep", kModel, "--vary", "pump_flow=1,x"},
        {"sweep", kModel, "--vary", "pump_flow=1,2", "--mode", "random"},
        {"sweep", kModel, "--vary", "pump_flow=1,2", "--output", "Volume#P1#p:median"},
        {"optimise", kModel, "--bound", "pump_flow=1:2"},
        {"optimise", kModel, "--bound", "pump_flow=2:1", "--objective", "final:Volume#P1#p"},
        {"optimise", kModel, "--bound", "pump_flow=1:2", "--objective", "ise:Volume#P1#p"},
        {"optimise", kModel, "--bound", "pump_flow=1:2", "--objective", "final:Volume#P1#p", "--algorithm", "magic"},
        {"jobs", "extra"},
        {"results"},
        {"results", "twelve"},
    };
    for (const auto& args : cases) {
        const CliResult r = remote(args, loggedIn());
        std::string shown;
        for (const auto& a : args) shown += " " + a;
        EXPECT_EQ(r.exitCode, 2) << "remote" << shown << "\n" << r.err;
        EXPECT_NE(r.err.find("usage:\n  tlmhub-cli remote login URL"), std::string::npos) << "remote" << shown;
    }
    const CliResult help = remote({"sweep", "--help"}, loggedIn());
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_EQ(help.out.rfind("usage:\n  tlmhub-cli remote login URL", 0), 0u) << help.out;
    // A job was never submitted: usage errors come before any request.
    EXPECT_EQ(mAdmin->get("/api/v1/jobs").json().size(), 0u);
}

TEST_F(RemoteCli, LoginWithAWrongPasswordSaysUnauthorized)
{
    const CliResult login =
        remote({"login", mUrl, "--user", "admin", "--password-stdin"}, noCredentials(), "not-the-password\n");
    EXPECT_EQ(login.exitCode, 1);
    EXPECT_EQ(login.err.rfind("error: unauthorized: ", 0), 0u) << login.err;
    EXPECT_FALSE(std::filesystem::exists(credentialsFile()));
}

TEST_F(RemoteCli, LoginWithoutATerminalNeedsPasswordStdin)
{
    const CliResult login = remote({"login", mUrl, "--user", "admin"}, noCredentials(), "admin-secret-pw\n");
    EXPECT_EQ(login.exitCode, 2);
    EXPECT_NE(login.err.find("--password-stdin"), std::string::npos) << login.err;
}

TEST_F(RemoteCli, HttpsThroughATlsProxy)
{
    TlsProxy proxy(mServer->port(), mDir / "tls");
    auto env = loggedIn();
    env["SSL_CERT_FILE"] = (mDir / "tls" / "cert.pem").string();
    env["TLMHUB_URL"] = "https://127.0.0.1:" + std::to_string(proxy.port());
    const auto csv = mDir / "https.csv";
    const CliResult run = remote({"run", kModel, "--csv", csv.string()}, env);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(readFile(csv), mAdmin->get("/api/v1/jobs/" + jobId(run) + "/results?format=csv").body);

    // By name: SNI and the certificate's DNS name.
    env["TLMHUB_URL"] = "https://localhost:" + std::to_string(proxy.port());
    const CliResult jobs = remote({"jobs"}, env);
    EXPECT_EQ(jobs.exitCode, 0) << jobs.err;
}

TEST_F(RemoteCli, AnUntrustedCertificateIsRefused)
{
    TlsProxy proxy(mServer->port(), mDir / "tls");
    auto env = loggedIn();
    const std::string authority = "127.0.0.1:" + std::to_string(proxy.port());
    env["TLMHUB_URL"] = "https://" + authority;
    const CliResult jobs = remote({"jobs"}, env);   // the system's store only
    EXPECT_EQ(jobs.exitCode, 1);
    EXPECT_NE(jobs.err.find("error: TLS handshake with " + authority +
                            " failed: the server's certificate is not trusted: self-signed certificate"),
              std::string::npos)
        << jobs.err;
    EXPECT_EQ(jobs.out, "");
}

TEST_F(RemoteCli, AConnectionFailureNamesHostAndPort)
{
    auto env = loggedIn();
    const std::string authority = "127.0.0.1:" + std::to_string(closedPort());
    env["TLMHUB_URL"] = "http://" + authority;
    const CliResult run = remote({"run", kModel}, env);
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.err, "error: cannot connect to " + authority + ": Connection refused\n");
}

// The tests below need POST /tokens and /studies (docs/studies.md); they fail until the
// server has them.

TEST_F(RemoteCli, LoginCreatesAnApiTokenAndStoresItPrivately)
{
    const CliResult login = remote({"login", mUrl, "--user", "admin", "--token-name", "ci token", "--password-stdin"},
                                   noCredentials(), std::string(kAdminPassword) + "\n");
    ASSERT_EQ(login.exitCode, 0) << login.err;
    EXPECT_EQ(login.out, "logged in to " + mUrl + " as admin: API token 'ci token' saved in " +
                             credentialsFile().string() + "\n");
    struct stat file {}, directory {};
    ASSERT_EQ(::stat(credentialsFile().c_str(), &file), 0);
    ASSERT_EQ(::stat(credentialsFile().parent_path().c_str(), &directory), 0);
    EXPECT_EQ(file.st_mode & 07777, 0600u);
    EXPECT_EQ(directory.st_mode & 07777, 0700u);
    const nlohmann::json stored = nlohmann::json::parse(readFile(credentialsFile()));
    EXPECT_EQ(stored["url"], mUrl);
    const std::string token = stored["token"].get<std::string>();
    EXPECT_TRUE(std::regex_match(token, std::regex("tlmh_[A-Za-z0-9_-]{43}"))) << token;

    const nlohmann::json tokens = mAdmin->get("/api/v1/tokens").json();
    ASSERT_EQ(tokens["tokens"].size(), 1u) << tokens;
    EXPECT_EQ(tokens["tokens"][0]["name"], "ci token");
    // The stored token is what the next commands use.
    const CliResult jobs = remote({"jobs"}, noCredentials());
    EXPECT_EQ(jobs.exitCode, 0) << jobs.err;
}

TEST_F(RemoteCli, SweepWritesTheStudysTable)
{
    const auto table = mDir / "sweep.csv";
    const CliResult sweep =
        remote({"sweep", kModel, "--vary", "pump_flow=1e-4:2e-4:3", "--csv", table.string()}, loggedIn());
    ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
    EXPECT_NE(sweep.out.find("3 runs, 0 failed, table " + table.string()), std::string::npos) << sweep.out;
    EXPECT_EQ(readFile(table),
              "run,ok,pump_flow\n0,1,0.0001\n1,1,0.00015000000000000001\n2,1,0.00020000000000000001\n");

    // Without --csv the table goes to stdout, alone; the progress to stderr.
    const CliResult listed = remote(
        {"sweep", kModel, "--vary", "pump_flow=1e-4,2e-4", "--vary", "relief_pressure=1e7,2e7", "--mode", "list"},
        loggedIn());
    ASSERT_EQ(listed.exitCode, 0) << listed.err;
    EXPECT_EQ(listed.out,
              "run,ok,pump_flow,relief_pressure\n0,1,0.0001,10000000\n1,1,0.00020000000000000001,20000000\n");
    EXPECT_EQ(listed.err.find('\r'), std::string::npos);
    EXPECT_NE(listed.err.find(": 100 % 2/2 runs, done\n"), std::string::npos) << listed.err;
}

TEST_F(RemoteCli, SweepOutputsBecomeColumns)
{
    const std::string variable = "ChamberPressure#P1#Pressure";
    const CliResult sweep =
        remote({"sweep", kModel, "--vary", "pump_flow=1e-4,2e-4", "--output", variable + ":final,max"}, loggedIn());
    ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
    EXPECT_EQ(sweep.out.substr(0, sweep.out.find('\n')),
              "run,ok,pump_flow," + variable + ":final," + variable + ":max");
    EXPECT_EQ(std::count(sweep.out.begin(), sweep.out.end(), '\n'), 3);
}

TEST_F(RemoteCli, OptimisePrintsTheBestPoint)
{
    const auto table = mDir / "optimise.csv";
    const CliResult optimise =
        remote({"optimise", kModel, "--bound", "pump_flow=5e-5:2e-4", "--objective", "final:ChamberPressure#P1#Pressure",
                "--algorithm", "nelder-mead", "--max-evaluations", "20", "--seed", "1", "--csv", table.string()},
               loggedIn());
    ASSERT_EQ(optimise.exitCode, 0) << optimise.err;
    EXPECT_TRUE(std::regex_search(optimise.out, std::regex("\nbest: run [0-9]+, objective [-0-9.e+]+\n  pump_flow = ")))
        << optimise.out;
    const std::string csv = readFile(table);
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "run,ok,pump_flow,objective");
}

// `--csv -` puts the table alone on standard output (the report goes to standard error), and
// the best objective printed reads back to the bits of the study's JSON.
TEST_F(RemoteCli, CsvDashPipesTheTableAndTheBestObjectiveIsPrintedExactly)
{
    const CliResult optimise =
        remote({"optimise", kModel, "--bound", "pump_flow=5e-5:2e-4", "--objective", "final:ChamberPressure#P1#Pressure",
                "--algorithm", "nelder-mead", "--max-evaluations", "20", "--seed", "1", "--csv", "-"},
               loggedIn());
    ASSERT_EQ(optimise.exitCode, 0) << optimise.err;
    EXPECT_EQ(optimise.out.rfind("run,ok,pump_flow,objective\n", 0), 0u) << optimise.out;
    EXPECT_FALSE(std::filesystem::exists("-")) << "a file named '-' was written";
    std::smatch m;
    ASSERT_TRUE(std::regex_search(optimise.err, m, std::regex("study ([0-9]+),.*\nbest: run [0-9]+, objective ([^\n]+)\n")))
        << optimise.err;
    const auto study = mAdmin->get("/api/v1/studies/" + m[1].str()).json();
    EXPECT_EQ(std::strtod(m[2].str().c_str(), nullptr), study["summary"]["best"]["objective"].get<double>()) << m[2];
    EXPECT_EQ(std::count(optimise.out.begin(), optimise.out.end(), '\n'), 21) << "header and 20 runs only";

    const CliResult sweep = remote({"sweep", kModel, "--vary", "pump_flow=1e-4,2e-4", "--csv", "-"}, loggedIn());
    ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
    EXPECT_EQ(sweep.out, "run,ok,pump_flow\n0,1,0.0001\n1,1,0.00020000000000000001\n");

    const CliResult run = remote({"run", kModel, "--csv", "-"}, loggedIn());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("\nok: "), std::string::npos) << run.err;   // after the progress lines
    std::smatch job;
    ASSERT_TRUE(std::regex_search(run.err, job, std::regex("job ([0-9]+) "))) << run.err;
    EXPECT_EQ(run.out, mAdmin->get("/api/v1/jobs/" + job[1].str() + "/results?format=csv").body);
}

} // namespace
} // namespace tlmhub::test
