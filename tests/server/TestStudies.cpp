// Studies end to end (docs/studies.md): a real server, real sockets, the shared models.
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <set>
#include <thread>

using namespace tlmhub::test;
namespace http = boost::beast::http;
namespace fs = std::filesystem;

namespace {

const std::string kPosition = "Position_Sensor#out#Value";

std::string exactText(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// A CSV's column by header name.
std::vector<double> csvColumn(const std::string& csv, const std::string& name)
{
    std::istringstream in(csv);
    std::string line, cell;
    std::getline(in, line);
    std::istringstream header(line);
    int index = -1;
    for (int i = 0; std::getline(header, cell, ','); ++i)
        if (cell == name) index = i;
    EXPECT_GE(index, 0) << "no column " << name;
    std::vector<double> values;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        for (int i = 0; std::getline(row, cell, ','); ++i)
            if (i == index) values.push_back(std::strtod(cell.c_str(), nullptr));
    }
    return values;
}

class StudiesBase : public ::testing::Test {
protected:
    static void startServer(std::vector<std::string> flags)
    {
        dataDir = new fs::path(freshTempDir("studies"));
        server = new ServerProcess(*dataDir, std::move(flags));
        createTestUsers(*server, {"alice", "bob"});
    }
    static void stopServer()
    {
        delete server;
        fs::remove_all(*dataDir);
        delete dataDir;
    }
    HttpClient as(const std::string& user) { return loggedInAs(*server, user); }
    std::int64_t submit(HttpClient& c, const nlohmann::json& study)
    {
        const auto r = c.post("/api/v1/studies", study);
        EXPECT_EQ(r.status, 201) << r.body;
        return r.status == 201 ? r.json()["id"].get<std::int64_t>() : 0;
    }
    nlohmann::json waitForStudy(HttpClient& c, std::int64_t id, int seconds = 180)
    {
        nlohmann::json study;
        for (int i = 0; i < seconds * 20; ++i) {
            study = c.get("/api/v1/studies/" + std::to_string(id)).json();
            const std::string state = study.value("state", "");
            if (state != "queued" && state != "running") return study;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        ADD_FAILURE() << "study " << id << " did not finish: " << study.dump();
        return study;
    }
    std::string cliCsv(const std::vector<std::pair<std::string, double>>& parameters, const std::string& name)
    {
        const fs::path out = *dataDir / (name + ".csv");
        const std::string cli = fs::path(TLMHUB_SERVER_BIN).parent_path() / "tlmhub-cli";
        std::string command = "'" + cli + "' run '" + kPositionServo.string() + "' --csv '" + out.string() + "'";
        for (const auto& [path, value] : parameters) command += " --param '" + path + "=" + exactText(value) + "'";
        EXPECT_EQ(std::system((command + " > /dev/null").c_str()), 0) << command;
        return readFile(out);
    }
    static fs::path* dataDir;
    static ServerProcess* server;
};
fs::path* StudiesBase::dataDir = nullptr;
ServerProcess* StudiesBase::server = nullptr;

// One worker: every run of a study follows the previous one on the same compiled simulation.
class StudiesOneWorker : public StudiesBase {
protected:
    static void SetUpTestSuite() { startServer({"--workers", "1"}); }
    static void TearDownTestSuite() { stopServer(); }
};

class Studies : public StudiesBase {
protected:
    static void SetUpTestSuite() { startServer({"--max-study-runs", "5000", "--max-studies-per-user", "3"}); }
    static void TearDownTestSuite() { stopServer(); }
};

} // namespace

// Each run of a sweep on one worker (setParameter + reset on one compiled simulation of a
// model with state: hydraulic volumes, a mass, an integrator) gives the bytes a fresh
// `tlmhub-cli run --param` gives for the same parameters.
TEST_F(StudiesOneWorker, SweepRunsAreByteEqualToCliRunsWithTheSameParameters)
{
    HttpClient alice = as("alice");
    const auto model = uploadModel(alice, kPositionServo, "servo");
    // One value needs all 17 digits: a parameter set from shorter text would differ.
    const std::vector<double> gains = {0.02, 0.026424912345678901, 0.035};
    const std::vector<double> volumes = {0.0003, 0.0005};
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"model_id", model},
                                   {"outputs", {{"variables", {kPosition}}, {"values", {"final", "max"}}, {"full", true}}},
                                   {"sweep", {{"parameters", {{"GainP.k", gains}, {"Cylinder_C.V_1", volumes}}}}}});
    const auto study = waitForStudy(alice, id);
    ASSERT_EQ(study["state"], "done") << study.dump();
    EXPECT_EQ(study["runs_done"], 6);
    EXPECT_EQ(study["runs_failed"], 0);

    const auto table = alice.get("/api/v1/studies/" + std::to_string(id) + "/results?format=json").json();
    // Parameters in the order of their names (a JSON object's members have no order).
    ASSERT_EQ(table["columns"], nlohmann::json({"run", "ok", "Cylinder_C.V_1", "GainP.k", kPosition + ":final",
                                                kPosition + ":max"}));
    ASSERT_EQ(table["rows"].size(), 6u);
    for (std::size_t run = 0; run < 6; ++run) {
        const nlohmann::json& row = table["rows"][run];
        // Grid order: the first parameter (Cylinder_C.V_1) varies slowest.
        const double volume = volumes[run / 3], gain = gains[run % 3];
        EXPECT_EQ(row[0], run);
        EXPECT_EQ(row[2].get<double>(), volume);
        EXPECT_EQ(row[3].get<double>(), gain);
        const auto csv = alice.get("/api/v1/studies/" + std::to_string(id) + "/runs/" + std::to_string(run) +
                                   "/results?format=csv");
        ASSERT_EQ(csv.status, 200) << csv.body;
        const std::string expected = cliCsv({{"GainP.k", gain}, {"Cylinder_C.V_1", volume}}, "run" + std::to_string(run));
        EXPECT_TRUE(csv.body == expected) << "run " << run << " differs from tlmhub-cli run --param";
        const std::vector<double> position = csvColumn(expected, kPosition);
        EXPECT_EQ(row[4].get<double>(), position.back());
        EXPECT_EQ(row[5].get<double>(), *std::max_element(position.begin(), position.end()));
    }
    // The parameters change the result: the runs are not all the same.
    EXPECT_NE(table["rows"][0][4], table["rows"][2][4]);

    const auto csvTable = alice.get("/api/v1/studies/" + std::to_string(id) + "/results?format=csv");
    ASSERT_EQ(csvTable.status, 200);
    EXPECT_EQ(csvTable.body.substr(0, csvTable.body.find('\n')),
              "run,ok,Cylinder_C.V_1,GainP.k," + kPosition + ":final," + kPosition + ":max");
    EXPECT_EQ(std::count(csvTable.body.begin(), csvTable.body.end(), '\n'), 7);
}

// A study of 10,000 runs takes its owner's turns; another user's job starts within a few runs.
TEST_F(StudiesOneWorker, AnotherUsersJobStartsWithinAFewRunsBehindALongStudy)
{
    HttpClient alice = as("alice");
    HttpClient bob = as("bob");
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", readFile(kPositionServo)},
                                   {"outputs", {{"variables", {kPosition}}}},
                                   {"sweep", {{"parameters", {{"GainP.k", {{"from", 0.01}, {"to", 0.04}, {"steps", 10000}}}}}}}});
    const std::string path = "/api/v1/studies/" + std::to_string(id);
    nlohmann::json study;
    for (int i = 0; i < 600; ++i) {
        study = alice.get(path).json();
        if (study["runs_done"].get<int>() >= 3) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_GE(study["runs_done"].get<int>(), 3) << study.dump();

    const auto submitted = bob.post("/api/v1/jobs", {{"hmf", readFile(kPositionServo)}});
    ASSERT_EQ(submitted.status, 201) << submitted.body;
    const int runsAtSubmit = alice.get(path).json()["runs_done"].get<int>();
    const std::string job = "/api/v1/jobs/" + std::to_string(submitted.json()["id"].get<std::int64_t>());
    int runsAtStart = -1;
    for (int i = 0; i < 2000 && runsAtStart < 0; ++i) {
        if (bob.get(job).json()["state"] != "queued") runsAtStart = alice.get(path).json()["runs_done"].get<int>();
        else std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_GE(runsAtStart, 0) << "bob's job never started";
    // The run in progress when the job came, plus what the polling lags behind.
    EXPECT_LE(runsAtStart - runsAtSubmit, 3) << "the job waited for " << runsAtStart - runsAtSubmit << " runs";

    // Cancelling stops the rest.
    const auto cancelled = alice.request(http::verb::delete_, path);
    EXPECT_TRUE(cancelled.status == 200 || cancelled.status == 202) << cancelled.body;
    study = waitForStudy(alice, id, 30);
    EXPECT_EQ(study["state"], "cancelled");
    EXPECT_LT(study["runs_done"].get<int>(), 10000);
    const auto rows = alice.get(path + "/results?format=json").json()["rows"].size();
    EXPECT_EQ(rows, study["runs_done"].get<std::size_t>());
}

// The bands are the mean and standard deviation over the runs at each time, and the
// correlations Pearson's r of the sampled parameters with the outputs, as computed here from
// each run's own result.
TEST_F(Studies, SensitivityBandsAndCorrelationsMatchTheRuns)
{
    HttpClient alice = as("alice");
    const int runs = 12;
    const auto id = submit(alice, {{"kind", "sensitivity"},
                                   {"hmf", readFile(kPositionServo)},
                                   {"outputs", {{"variables", {kPosition}}, {"values", {"final", "max"}}, {"full", true}}},
                                   {"sensitivity", {{"runs", runs}, {"seed", 7},
                                                    {"parameters", {{"GainP.k", {{"distribution", "normal"}, {"mean", 0.0264}, {"sd", 0.004}}},
                                                                    {"Cylinder_C.V_1", {{"distribution", "uniform"}, {"min", 0.0002}, {"max", 0.0006}}}}}}}});
    const auto study = waitForStudy(alice, id);
    ASSERT_EQ(study["state"], "done") << study.dump();
    const std::string path = "/api/v1/studies/" + std::to_string(id);
    const auto table = alice.get(path + "/results?format=json").json();
    ASSERT_EQ(table["rows"].size(), static_cast<std::size_t>(runs));

    std::vector<std::vector<double>> positions;
    for (int run = 0; run < runs; ++run) {
        const auto csv = alice.get(path + "/runs/" + std::to_string(run) + "/results?format=csv");
        ASSERT_EQ(csv.status, 200);
        positions.push_back(csvColumn(csv.body, kPosition));
    }
    const auto bands = alice.get(path + "/bands?format=json").json();
    const auto& v = bands["variables"][kPosition];
    ASSERT_EQ(v["mean"].size(), positions[0].size());
    for (std::size_t i = 0; i < positions[0].size(); i += 97) {
        double mean = 0, squares = 0;
        for (const auto& p : positions) mean += p[i] / runs;
        for (const auto& p : positions) squares += (p[i] - mean) * (p[i] - mean);
        const double sd = std::sqrt(squares / (runs - 1));
        EXPECT_NEAR(v["mean"][i].get<double>(), mean, 1e-12 * (1 + std::abs(mean))) << "sample " << i;
        EXPECT_NEAR(v["sd"][i].get<double>(), sd, 1e-9 * (1 + sd)) << "sample " << i;
        EXPECT_NEAR(v["plus_2sd"][i].get<double>(), mean + 2 * sd, 1e-9 * (1 + std::abs(mean)));
    }
    // Pearson's r of GainP.k with the final position.
    ASSERT_EQ(table["columns"][3], "GainP.k");
    ASSERT_EQ(table["columns"][4], kPosition + ":final");
    double mx = 0, my = 0;
    for (const auto& row : table["rows"]) mx += row[3].get<double>() / runs, my += row[4].get<double>() / runs;
    double sxy = 0, sxx = 0, syy = 0;
    for (const auto& row : table["rows"]) {
        const double dx = row[3].get<double>() - mx, dy = row[4].get<double>() - my;
        sxy += dx * dy, sxx += dx * dx, syy += dy * dy;
    }
    const double r = sxy / std::sqrt(sxx * syy);
    EXPECT_NEAR(study["summary"]["correlations"]["GainP.k"][kPosition + ":final"].get<double>(), r, 1e-9);
    const auto csv = alice.get(path + "/bands?format=csv");
    EXPECT_EQ(csv.body.substr(0, csv.body.find('\n')),
              "time," + kPosition + ":mean-2sd," + kPosition + ":mean-sd," + kPosition + ":mean," + kPosition +
                  ":mean+sd," + kPosition + ":mean+2sd");
}

// event.study.progress carries every run's row once, and a last event with the final state.
TEST_F(Studies, ProgressRowsStreamOverTheWebSocket)
{
    HttpClient alice = as("alice");
    // Connected first, so that the subscription comes while the runs go on.
    WsClient ws(server->port(), alice.login("alice", testPassword("alice")));
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", readFile(kPositionServo)},
                                   {"stop", 1.5},   // runs long enough to subscribe meanwhile; what they simulate does not matter
                                   {"outputs", {{"variables", {kPosition}}}},
                                   {"sweep", {{"parameters", {{"GainP.k", {{"from", 0.01}, {"to", 0.04}, {"steps", 200}}}}}}}});
    const auto reply = ws.call("study.subscribe", {{"study_id", id}});
    ASSERT_EQ(reply["type"], "reply") << reply.dump();
    std::set<std::int64_t> runs;
    std::string state;
    auto take = [&](const nlohmann::json& event) {
        if (event.value("type", "") != "event.study.progress") return;
        for (const auto& row : event["rows"]) EXPECT_TRUE(runs.insert(row[0].get<std::int64_t>()).second);
        state = event["state"].get<std::string>();
    };
    for (const auto& event : ws.events) take(event);
    while (state != "done" && state != "failed" && state != "cancelled") {
        const auto event = ws.receive(60000);
        ASSERT_FALSE(event.is_null()) << "no final event";
        take(event);
    }
    EXPECT_EQ(state, "done");
    const auto study = alice.get("/api/v1/studies/" + std::to_string(id)).json();
    // Rows finished before the subscription are in the table, not in the events; each event
    // row is one of the table's, once.
    EXPECT_EQ(study["runs_done"], 200);
    EXPECT_FALSE(runs.empty());
    if (!runs.empty()) {
        EXPECT_LT(*runs.rbegin(), 200);
    }
}

TEST_F(Studies, OnlyTheOwnerSeesAndCancelsAStudy)
{
    HttpClient alice = as("alice");
    HttpClient bob = as("bob");
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", readFile(kPositionServo)},
                                   {"outputs", {{"full", true}}},
                                   {"sweep", {{"parameters", {{"GainP.k", {0.02}}}}}}});
    waitForStudy(alice, id);
    const std::string path = "/api/v1/studies/" + std::to_string(id);
    for (const std::string& target : {path, path + "/results?format=csv", path + "/runs/0/results?format=csv", path + "/bands"})
        EXPECT_EQ(bob.get(target).status, 404) << target;
    EXPECT_EQ(bob.request(http::verb::delete_, path).status, 404);
    EXPECT_TRUE(bob.get("/api/v1/studies").json()["studies"].empty());
    WsClient ws(server->port(), bob.login("bob", testPassword("bob")));
    EXPECT_EQ(ws.call("study.subscribe", {{"study_id", id}})["error"]["code"], "not_found");
    // The owner deletes a finished study with its runs.
    EXPECT_EQ(alice.get(path + "/runs/0/results?format=csv").status, 200);
    EXPECT_EQ(alice.request(http::verb::delete_, path).status, 204);
    EXPECT_EQ(alice.get(path).status, 404);
}

TEST_F(Studies, BadStudiesAreRefusedWithErrorsNamingWhatIsWrong)
{
    HttpClient alice = as("alice");
    const std::string hmf = readFile(kPositionServo);
    auto refused = [&](const nlohmann::json& study, int status, const std::string& code, const std::string& words) {
        const auto r = alice.post("/api/v1/studies", study);
        EXPECT_EQ(r.status, status) << r.body;
        EXPECT_EQ(r.json()["error"]["code"], code) << r.body;
        EXPECT_NE(r.json()["error"]["message"].get<std::string>().find(words), std::string::npos) << r.body;
    };
    const nlohmann::json sweep = {{"parameters", {{"GainP.k", {0.02, 0.03}}}}};
    refused({{"kind", "dance"}, {"hmf", hmf}}, 400, "schema_violation", "kind");
    refused({{"kind", "sweep"}, {"sweep", sweep}}, 400, "bad_request", "model_id or hmf");
    refused({{"kind", "sweep"}, {"hmf", hmf}, {"sweep", {{"parameters", {{"NoSuch.k", {1}}}}}}}, 400,
            "invalid_parameter", "NoSuch");
    refused({{"kind", "sweep"}, {"hmf", hmf}, {"sweep", sweep}, {"outputs", {{"variables", {"Nothing#out#Value"}}}}}, 400,
            "bad_request", "Nothing#out#Value");
    refused({{"kind", "sweep"}, {"hmf", hmf}, {"sweep", {{"mode", "list"}, {"parameters", {{"GainP.k", {1, 2}}, {"GainI.k", {1}}}}}}},
            400, "bad_request", "equal length");
    refused({{"kind", "sweep"}, {"hmf", hmf}, {"sweep", {{"parameters", {{"GainP.k", {{"from", 0}, {"to", 1}, {"steps", 5001}}}}}}}},
            422, "limit_exceeded", "5000");
    // Full results of 5000 runs of 2 MB each cannot fit in the study's 512 MiB.
    refused({{"kind", "sweep"}, {"hmf", hmf}, {"outputs", {{"full", true}}},
             {"sweep", {{"parameters", {{"GainP.k", {{"from", 0}, {"to", 1}, {"steps", 5000}}}}}}}},
            422, "limit_exceeded", "--max-study-bytes");
    refused({{"kind", "optimise"}, {"hmf", hmf},
             {"optimise", {{"parameters", {{"GainP.k", {{"min", 1}, {"max", 0}}}}},
                           {"objective", {{"terms", {{{"function", "final"}, {"variable", kPosition}}}}}}}}},
            400, "bad_request", "GainP.k");
    refused({{"kind", "sensitivity"}, {"hmf", hmf},
             {"sensitivity", {{"runs", 10}, {"parameters", {{"GainP.k", {{"distribution", "normal"}, {"mean", 1}, {"sd", 0.1}}}}}}}},
            400, "bad_request", "outputs.variables");
}

// The optimisers find the minimum a fine sweep finds, in fewer runs: the integral of the
// squared error between Position Servo's position and its step reference, over the two gains
// of its PI controller (an interior minimum, with a second valley on the bound GainI.k = 0).
TEST_F(Studies, OptimisersReachTheMinimumOfAFineSweep)
{
    HttpClient alice = as("alice");
    const std::string hmf = readFile(kPositionServo);
    const nlohmann::json bounds = {{"GainP.k", {{"min", 0.005}, {"max", 0.08}}}, {"GainI.k", {{"min", 0.0}, {"max", 0.01}}}};
    const nlohmann::json objective = {{"terms", {{{"function", "ise"}, {"variable", kPosition}, {"reference_variable", "Step#out#Value"}}}}};
    const int steps = 16;
    // Position Servo's step comes at 1 s of its 3: the second after it is where the gains
    // show, and it makes these 656 runs a third cheaper (under the sanitizers most of all).
    const double stop = 2.0;
    const auto sweepId = submit(alice, {{"kind", "sweep"}, {"hmf", hmf}, {"stop", stop}, {"objective", objective},
                                        {"sweep", {{"parameters", {{"GainP.k", {{"from", 0.005}, {"to", 0.08}, {"steps", steps}}},
                                                                   {"GainI.k", {{"from", 0.0}, {"to", 0.01}, {"steps", steps}}}}}}}});
    const auto sweep = waitForStudy(alice, sweepId);
    ASSERT_EQ(sweep["state"], "done") << sweep.dump();
    const double sweepMinimum = sweep["summary"]["best"]["objective"].get<double>();
    const double bestGainI = sweep["summary"]["best"]["parameters"]["GainI.k"].get<double>();
    EXPECT_GT(bestGainI, 0.0) << "the minimum is not interior";
    EXPECT_LT(bestGainI, 0.01) << "the minimum is not interior";
    for (const std::string algorithm : {"complex-rf", "nelder-mead"}) {
        const auto id = submit(alice, {{"kind", "optimise"}, {"hmf", hmf}, {"stop", stop},
                                       {"optimise", {{"algorithm", algorithm}, {"parameters", bounds}, {"objective", objective},
                                                     {"max_evaluations", 200}, {"seed", 1}}}});
        const auto study = waitForStudy(alice, id);
        ASSERT_EQ(study["state"], "done") << study.dump();
        EXPECT_LE(study["runs_done"].get<int>(), 200);
        const double found = study["summary"]["best"]["objective"].get<double>();
        EXPECT_LE(found, sweepMinimum * 1.01) << algorithm << " reached " << found << ", the sweep " << sweepMinimum;
        // The best is the table's lowest objective, at the parameters of its row.
        const auto table = alice.get("/api/v1/studies/" + std::to_string(id) + "/results?format=json").json();
        double lowest = INFINITY;
        for (const auto& row : table["rows"])
            if (!row.back().is_null()) lowest = std::min(lowest, row.back().get<double>());
        EXPECT_EQ(found, lowest) << algorithm;
    }
}

namespace {

// data/RoundDivide.hmf: a run with |Round.in| < 0.5 divides by zero and fails ("Division by
// zero"); one with Round.in in [0.5, 1.5) gives Divide.in1.
const std::string kDivider = readFile(kRoundDivide);
const std::string kQuotient = "Divide#out#Value";

bool mentions(const nlohmann::json& text, const std::string& words)
{
    return text.is_string() && text.get<std::string>().find(words) != std::string::npos;
}

} // namespace

// Every run fails: the study fails too, naming the reason, and its failed runs are counted
// by reason with the first run that failed so.
TEST_F(Studies, AStudyWhoseRunsAllFailEndsFailedWithItsReasonsCounted)
{
    HttpClient alice = as("alice");
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", kDivider},
                                   {"outputs", {{"variables", {kQuotient}}}},
                                   {"sweep", {{"parameters", {{"Round.in", {0.1, -0.2, 0.3, 0.4, 0.0}}}}}}});
    const auto study = waitForStudy(alice, id);
    EXPECT_EQ(study["state"], "failed") << study.dump();
    EXPECT_EQ(study["runs_done"], 0);
    EXPECT_EQ(study["runs_failed"], 5);
    EXPECT_TRUE(mentions(study["error"], "Division by zero")) << study.dump();
    const nlohmann::json& reasons = study["summary"]["failure_reasons"];
    ASSERT_EQ(reasons.size(), 1u) << study.dump();
    EXPECT_TRUE(mentions(reasons[0]["message"], "Division by zero")) << reasons.dump();
    EXPECT_EQ(reasons[0]["count"], 5);
    EXPECT_EQ(reasons[0]["first_run"], 0);
}

// The progress events of a running study carry its failed runs by reason, as its summary.
TEST_F(Studies, ProgressEventsCountTheFailedRunsByReason)
{
    HttpClient alice = as("alice");
    WsClient ws(server->port(), alice.login("alice", testPassword("alice")));
    // Run 1 fails, the others succeed; long enough to be running when the subscription comes.
    std::vector<double> values(4000, 1.0);
    values[1] = 0.3;
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", kDivider},
                                   {"stop", 10},
                                   {"outputs", {{"variables", {kQuotient}}}},
                                   {"sweep", {{"parameters", {{"Round.in", values}}}}}});
    const auto reply = ws.call("study.subscribe", {{"study_id", id}});
    ASSERT_EQ(reply["type"], "reply") << reply.dump();
    nlohmann::json reasons;
    auto take = [&](const nlohmann::json& event) {
        if (event.value("type", "") == "event.study.progress" && event.contains("failure_reasons"))
            reasons = event["failure_reasons"];
    };
    for (const auto& event : ws.events) take(event);
    while (reasons.is_null()) {
        const auto event = ws.receive(60000);
        ASSERT_FALSE(event.is_null()) << "no event with failure_reasons";
        ASSERT_NE(event.value("state", ""), "done") << "the study ended with no event carrying failure_reasons: " << event.dump();
        take(event);
    }
    ASSERT_EQ(reasons.size(), 1u) << reasons.dump();
    EXPECT_TRUE(mentions(reasons[0]["message"], "Division by zero")) << reasons.dump();
    EXPECT_EQ(reasons[0]["count"], 1);
    EXPECT_EQ(reasons[0]["first_run"], 1);
    const std::string path = "/api/v1/studies/" + std::to_string(id);
    EXPECT_EQ(alice.get(path).json()["summary"]["failure_reasons"], reasons);
    const auto cancelled = alice.request(http::verb::delete_, path);
    EXPECT_TRUE(cancelled.status == 200 || cancelled.status == 202) << cancelled.body;
    EXPECT_EQ(waitForStudy(alice, id, 60)["state"], "cancelled");
}

// A sensitivity study some of whose runs failed says from how many runs its bands and
// correlations come: the successful ones, whose rows the table marks ok.
TEST_F(Studies, SensitivityBandsAndCorrelationsCountOnlyTheRunsThatSucceeded)
{
    HttpClient alice = as("alice");
    const int runs = 20;
    const auto id = submit(alice, {{"kind", "sensitivity"},
                                   {"hmf", kDivider},
                                   {"outputs", {{"variables", {kQuotient}}, {"values", {"final"}}}},
                                   {"sensitivity", {{"runs", runs}, {"seed", 7},
                                                    {"parameters", {{"Round.in", {{"distribution", "uniform"}, {"min", 0.0}, {"max", 1.4}}},
                                                                    {"Divide.in1", {{"distribution", "normal"}, {"mean", 3}, {"sd", 1}}}}}}}});
    const auto study = waitForStudy(alice, id);
    ASSERT_EQ(study["state"], "done") << study.dump();
    const std::string path = "/api/v1/studies/" + std::to_string(id);
    const auto table = alice.get(path + "/results?format=json").json();
    ASSERT_EQ(table["rows"].size(), static_cast<std::size_t>(runs));
    int succeeded = 0;
    std::int64_t firstFailed = -1;
    for (const auto& row : table["rows"]) {
        if (row[1] == 1) ++succeeded;
        else if (firstFailed < 0) firstFailed = row[0].get<std::int64_t>();
    }
    // The seed gives both kinds of run.
    ASSERT_GT(succeeded, 1);
    ASSERT_LT(succeeded, runs);
    EXPECT_EQ(study["runs_done"], succeeded);
    EXPECT_EQ(study["runs_failed"], runs - succeeded);

    const auto bands = alice.get(path + "/bands?format=json");
    ASSERT_EQ(bands.status, 200) << bands.body;
    EXPECT_EQ(bands.json()["n"], succeeded) << bands.body;
    EXPECT_EQ(study["summary"]["correlations_n"], succeeded) << study.dump();
    EXPECT_TRUE(study["summary"]["correlations"]["Divide.in1"][kQuotient + ":final"].is_number()) << study.dump();

    const nlohmann::json& reasons = study["summary"]["failure_reasons"];
    ASSERT_EQ(reasons.size(), 1u) << study.dump();
    EXPECT_TRUE(mentions(reasons[0]["message"], "Division by zero")) << reasons.dump();
    EXPECT_EQ(reasons[0]["count"], runs - succeeded);
    EXPECT_EQ(reasons[0]["first_run"], firstFailed);
}

// An optimisation none of whose runs succeeded has no best point: it fails, saying why.
TEST_F(Studies, AnOptimisationWithNoSuccessfulRunEndsFailed)
{
    HttpClient alice = as("alice");
    const auto id = submit(alice, {{"kind", "optimise"},
                                   {"hmf", kDivider},
                                   {"optimise", {{"parameters", {{"Round.in", {{"min", -0.4}, {"max", 0.4}}}}},
                                                 {"objective", {{"terms", {{{"function", "final"}, {"variable", kQuotient}}}}}},
                                                 {"max_evaluations", 12}, {"seed", 1}}}});
    const auto study = waitForStudy(alice, id);
    EXPECT_EQ(study["state"], "failed") << study.dump();
    EXPECT_EQ(study["runs_done"], 0);
    EXPECT_GT(study["runs_failed"].get<int>(), 0);
    EXPECT_TRUE(mentions(study["error"], "Division by zero")) << study.dump();
    EXPECT_FALSE(study["summary"].contains("best")) << study.dump();
    ASSERT_EQ(study["summary"]["failure_reasons"].size(), 1u) << study.dump();
    EXPECT_EQ(study["summary"]["failure_reasons"][0]["count"], study["runs_failed"]);
}

// max_failed_fraction: once 10 runs have finished, a study whose failed share passes it ends
// failed without the rest of its runs (which here would all succeed).
TEST_F(Studies, MaxFailedFractionEndsAStudyEarly)
{
    HttpClient alice = as("alice");
    std::vector<double> values(12, 0.2);
    values.resize(60, 1.0);
    const auto id = submit(alice, {{"kind", "sweep"},
                                   {"hmf", kDivider},
                                   {"max_failed_fraction", 0.5},
                                   {"outputs", {{"variables", {kQuotient}}}},
                                   {"sweep", {{"parameters", {{"Round.in", values}}}}}});
    const auto study = waitForStudy(alice, id);
    EXPECT_EQ(study["state"], "failed") << study.dump();
    EXPECT_TRUE(mentions(study["error"], "max_failed_fraction")) << study.dump();
    EXPECT_TRUE(mentions(study["error"], "Division by zero")) << study.dump();
    const int finished = study["runs_done"].get<int>() + study["runs_failed"].get<int>();
    EXPECT_GE(finished, 10);
    EXPECT_LT(finished, 60);
    EXPECT_GE(study["runs_failed"].get<int>(), 10);
}

TEST_F(Studies, MaxFailedFractionOutsideZeroToOneIsRefused)
{
    HttpClient alice = as("alice");
    const nlohmann::json sweep = {{"parameters", {{"Round.in", {1.0, 1.2}}}}};
    for (const nlohmann::json& bad : {nlohmann::json(1.5), nlohmann::json(-0.1), nlohmann::json("half"), nlohmann::json(nullptr)}) {
        const auto r = alice.post("/api/v1/studies", {{"kind", "sweep"}, {"hmf", kDivider}, {"sweep", sweep},
                                                      {"max_failed_fraction", bad}});
        EXPECT_EQ(r.status, 400) << bad.dump() << ": " << r.body;
        // The schema refuses it (StudyCreate), and the request's own check too (TestStudyParts).
        const std::string code = r.json()["error"].value("code", "");
        EXPECT_TRUE(code == "schema_violation" || code == "bad_request") << r.body;
        EXPECT_TRUE(mentions(r.json()["error"]["message"], "max_failed_fraction")) << r.body;
    }
    // 0 and 1 are in range.
    for (const double fine : {0.0, 1.0}) {
        const auto id = submit(alice, {{"kind", "sweep"}, {"hmf", kDivider}, {"sweep", sweep}, {"max_failed_fraction", fine}});
        EXPECT_EQ(waitForStudy(alice, id)["state"], "done");
    }
}
