// hopsancli, the HopsanCLI-compatible command line (docs/hopsancli.md): the real binary run
// on models of ../shared/hopsan-models (read in place), its exit codes, its messages and the
// files it writes, checked against tlmhub-cli's results of the same model.
#include "ChildProcess.h"
#include "server/TemporaryDirectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace tlmhub::test {
namespace {

namespace fs = std::filesystem;

const std::string kShared = TLMHUB_SHARED_DIR;
const std::string kSubSystemModel = kShared + "/hopsan-models/Example Models/Sub System Example.hmf";
const std::string kBouncingBallHvc = kShared + "/hopsan-models/Example Models Validations/Bouncing Ball.hvc";

using Line = std::vector<std::string>;

std::vector<std::string> split(const std::string& text, char delimiter)
{
    std::vector<std::string> fields;
    std::stringstream in(text);
    for (std::string field; std::getline(in, field, delimiter);) fields.push_back(field);
    return fields;
}

std::vector<Line> readLines(const fs::path& path)
{
    std::ifstream in(path);
    EXPECT_TRUE(in) << "hopsancli did not write " << path;
    std::vector<Line> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(split(line, ','));
    return lines;
}

std::string readText(const fs::path& path)
{
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

double number(const std::string& text)
{
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    EXPECT_TRUE(!text.empty() && *end == '\0') << "not a number: '" << text << "'";
    return value;
}

// The line named `name` in a rows file (its fields), or null.
const Line* lineNamed(const std::vector<Line>& lines, const std::string& name)
{
    for (const Line& line : lines)
        if (!line.empty() && line[0] == name) return &line;
    return nullptr;
}

// Whether a value printed as "%e" (6 decimals) is `expected`.
bool printedAs(double printed, double expected)
{
    return std::fabs(printed - expected) <= 6e-7 * std::fabs(expected) + 1e-300;
}

class HopsanCli : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        ASSERT_TRUE(fs::exists(kSubSystemModel))
            << "../shared is missing: " << kSubSystemModel << " (TLMHUB_SHARED_DIR=" << kShared << ")";
        ASSERT_TRUE(fs::exists(kBouncingBallHvc)) << "../shared is missing: " << kBouncingBallHvc;
    }

    void SetUp() override { mDir = makeTemporaryDirectory("hopsancli-test"); }
    void TearDown() override { fs::remove_all(mDir); }

    CliResult hopsancli(const std::vector<std::string>& args) const
    {
        std::vector<std::string> argv = {TLMHUB_HOPSANCLI_BIN};
        argv.insert(argv.end(), args.begin(), args.end());
        return runProgram(argv);
    }

    // The full results (rows) of the Sub System Example with `extra` options.
    std::vector<Line> fullRows(const std::vector<std::string>& extra, const std::string& file = "full.csv") const
    {
        std::vector<std::string> args = {"-m", kSubSystemModel, "--resultsFullCSV", (mDir / file).string()};
        args.insert(args.end(), extra.begin(), extra.end());
        const CliResult r = hopsancli(args);
        EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
        return readLines(mDir / file);
    }

    fs::path mDir;
};

TEST_F(HopsanCli, FullCsvRowsAreTheEnginesResultsInHopsanCliOrder)
{
    const std::vector<Line> rows = fullRows({"-s", "hmf"});
    // The engine's own results of the same model: tlmhub-cli run --csv (a column each).
    const CliResult ref = runCli({"run", kSubSystemModel, "--csv", (mDir / "ref.csv").string(), "--threads", "1"});
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    const std::vector<Line> table = readLines(mDir / "ref.csv");
    ASSERT_GT(table.size(), 1u);
    const Line& header = table[0];

    // Every variable line in the engine's order, each subsystem's Time line right after its
    // content (core.md §4.5), the root's last.
    std::vector<std::string> variableNames;
    std::vector<std::string> timeLines;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::string& name = rows[i].at(0);
        if (name.size() >= 4 && name.compare(name.size() - 4, 4, "Time") == 0) {
            timeLines.push_back(name);
            const std::string prefix = name.substr(0, name.size() - 4);
            ASSERT_GT(i, 0u);
            if (!prefix.empty()) {
                EXPECT_EQ(rows[i - 1][0].rfind(prefix, 0), 0u) << name << " follows " << rows[i - 1][0];
                if (i + 1 < rows.size()) {
                    EXPECT_NE(rows[i + 1][0].rfind(prefix, 0), 0u) << rows[i + 1][0];
                }
            }
        } else {
            variableNames.push_back(name);
        }
    }
    EXPECT_EQ(timeLines, (std::vector<std::string>{"Servo1$Time", "Servo2$Time", "Time"}));
    EXPECT_EQ(rows.back()[0], "Time");
    ASSERT_EQ(variableNames, std::vector<std::string>(header.begin() + 1, header.end()));
    const Line* pressure = lineNamed(rows, "Servo1$4_3_Servo_Valve#PA#Pressure");
    ASSERT_NE(pressure, nullptr);
    EXPECT_EQ((*pressure)[1], "");
    EXPECT_EQ((*pressure)[2], "Pa");

    // 2048 samples (the file's setting), "%e" numbers equal to the engine's.
    for (const Line& line : rows) {
        ASSERT_EQ(line.size(), 3u + 2048u) << line[0];
        std::size_t column = 0;
        const bool isTime = line[0].size() >= 4 && line[0].compare(line[0].size() - 4, 4, "Time") == 0;
        if (!isTime) column = static_cast<std::size_t>(std::find(header.begin(), header.end(), line[0]) - header.begin());
        for (std::size_t k = 0; k < 2048; ++k) {
            const std::string& printed = line[3 + k];
            ASSERT_EQ(printed.find('e'), printed.size() - 4) << line[0] << " sample " << k << ": " << printed;
            const double expected = number(table[1 + k].at(column));
            ASSERT_TRUE(printedAs(number(printed), expected))
                << line[0] << " sample " << k << ": " << printed << " vs " << table[1 + k][column];
        }
    }
    EXPECT_EQ(lineNamed(rows, "Time")->at(3), "0.000000e+00");
    EXPECT_EQ(lineNamed(rows, "Time")->back(), "1.000000e+01");
}

TEST_F(HopsanCli, ColsIsTheTransposeOfRows)
{
    const std::vector<Line> rows = fullRows({"-s", "hmf"}, "rows.csv");
    const std::vector<Line> cols = fullRows({"-s", "hmf", "--resultsCSVSort", "cols"}, "cols.csv");
    ASSERT_EQ(cols.size(), 3u + 2048u);
    // The alias line: every field empty (the split drops the empty field after its last comma).
    std::ifstream in(mDir / "cols.csv");
    std::string names, aliases;
    std::getline(in, names);
    std::getline(in, aliases);
    EXPECT_EQ(aliases, std::string(rows.size() - 1, ','));
    for (std::size_t c = 0; c < cols.size(); ++c) {
        if (c == 1) continue;
        ASSERT_EQ(cols[c].size(), rows.size()) << "line " << c;
        for (std::size_t r = 0; r < rows.size(); ++r) ASSERT_EQ(cols[c][r], rows[r][c]) << "line " << c << " field " << r;
    }
}

TEST_F(HopsanCli, FinalCsvHoldsTheLastValues)
{
    const CliResult r = hopsancli({"-m", kSubSystemModel, "-s", "hmf", "--resultsFullCSV", (mDir / "full.csv").string(),
                                   "--resultsFinalCSV", (mDir / "final.csv").string()});
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::vector<Line> full = readLines(mDir / "full.csv");
    const std::vector<Line> final = readLines(mDir / "final.csv");
    ASSERT_EQ(final.size(), full.size());
    for (std::size_t i = 0; i < full.size(); ++i) {
        ASSERT_EQ(final[i].size(), 4u) << final[i][0];
        EXPECT_EQ(final[i][0], full[i][0]);
        EXPECT_EQ(final[i][2], full[i][2]);
        EXPECT_TRUE(printedAs(number(final[i][3]), number(full[i].back())))
            << final[i][0] << ": " << final[i][3] << " vs " << full[i].back();
    }
    EXPECT_EQ(lineNamed(final, "Servo1$Time")->at(3), "1.000000e+01");
}

TEST_F(HopsanCli, SimulateTakesStopStepStopAndStartStepStop)
{
    // -s stop: the file's start (0) and step (0.001); every step from 0 to 2 is one of the
    // file's 2048 samples (2001 of them, core.md §4.2).
    const Line time1 = *lineNamed(fullRows({"-s", "2"}, "a.csv"), "Time");
    EXPECT_EQ(time1.size(), 3u + 2001u);
    EXPECT_EQ(time1[4], "1.000000e-03");
    EXPECT_EQ(time1[3], "0.000000e+00");
    EXPECT_EQ(time1.back(), "2.000000e+00");
    // -s step,stop: every step of 0.002 up to 3 is a sample (1501 of them, fewer than 2048).
    const Line time2 = *lineNamed(fullRows({"-s", "0.002,3"}, "b.csv"), "Time");
    ASSERT_EQ(time2.size(), 3u + 1501u);
    EXPECT_EQ(time2[4], "2.000000e-03");
    EXPECT_EQ(time2.back(), "3.000000e+00");
    // -s start,step,stop, and -l the number of samples.
    const std::vector<Line> rows3 = fullRows({"-s", "1,0.001,4", "-l", "31"}, "c.csv");
    const Line time3 = *lineNamed(rows3, "Time");
    ASSERT_EQ(time3.size(), 3u + 31u);
    EXPECT_EQ(time3[3], "1.000000e+00");
    EXPECT_EQ(time3[4], "1.100000e+00");
    EXPECT_EQ(time3.back(), "4.000000e+00");
    EXPECT_EQ(lineNamed(rows3, "Servo2$Time")->size(), 3u + 31u);
}

TEST_F(HopsanCli, WithoutSimulateNothingRunsAndTheExitCodeIsOne)
{
    // As HopsanCLI: -m alone loads and exports, but only a finished simulation is a success.
    const CliResult r = hopsancli({"-m", kSubSystemModel, "--parameterExport", (mDir / "p.csv").string(),
                                   "--resultsFullCSV", (mDir / "full.csv").string()});
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_NE(r.out.find("HopsanCLI Done!"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(mDir / "p.csv"));
    EXPECT_TRUE(readLines(mDir / "full.csv").empty());
}

TEST_F(HopsanCli, ASimulationAComponentStopsExitsOneAndKeepsItsResults)
{
    const std::string model = kShared + "/hopsan-models/Component Test/SignalComponent Test/Logic/StopTest.hmf";
    ASSERT_TRUE(fs::exists(model)) << "../shared is missing: " << model;
    const CliResult r = hopsancli({"-m", model, "-s", "hmf", "--resultsFinalCSV", (mDir / "final.csv").string()});
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_NE(r.out.find("Error: Simulation was aborted!\n"), std::string::npos) << r.out;
    EXPECT_EQ(lineNamed(readLines(mDir / "final.csv"), "Time")->at(3), "5.000000e+00");
}

TEST_F(HopsanCli, ParameterExportThenImportRoundTripsAndChangesAResult)
{
    const fs::path exported = mDir / "parameters.csv";
    const CliResult r = hopsancli({"-m", kSubSystemModel, "-s", "hmf", "--parameterExport", exported.string(),
                                   "--resultsFinalCSV", (mDir / "before.csv").string()});
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::string text = readText(exported);
    EXPECT_EQ(text.rfind("self#Force,1000\n", 0), 0u) << text.substr(0, 200);
    EXPECT_NE(text.find("\nForceSource1#F#Value,Force\n"), std::string::npos);
    EXPECT_NE(text.find("\nServo1$#PGain,0.003\n"), std::string::npos);
    EXPECT_NE(text.find("\nServo1$Gain#"), std::string::npos);

    // The file as written imports as it is: the same export, the same results.
    const CliResult same = hopsancli({"-m", kSubSystemModel, "-s", "hmf", "--parameterImport", exported.string(),
                                      "--parameterExport", (mDir / "again.csv").string(), "--resultsFinalCSV",
                                      (mDir / "same.csv").string()});
    ASSERT_EQ(same.exitCode, 0) << same.out;
    EXPECT_EQ(same.out.find("Error"), std::string::npos) << same.out;
    EXPECT_EQ(readText(mDir / "again.csv"), text);
    EXPECT_EQ(readText(mDir / "same.csv"), readText(mDir / "before.csv"));

    // An edited value changes the result: Force feeds both force sources.
    std::string edited = text;
    edited.replace(0, std::string("self#Force,1000").size(), "self#Force,2500");
    std::ofstream(mDir / "edited.csv") << edited;
    const CliResult changed = hopsancli({"-m", kSubSystemModel, "-s", "hmf", "--parameterImport",
                                         (mDir / "edited.csv").string(), "--resultsFinalCSV",
                                         (mDir / "after.csv").string()});
    ASSERT_EQ(changed.exitCode, 0) << changed.out;
    EXPECT_EQ(lineNamed(readLines(mDir / "before.csv"), "ForceSource1#P1#Force")->at(3), "1.000000e+03");
    EXPECT_EQ(lineNamed(readLines(mDir / "after.csv"), "ForceSource1#P1#Force")->at(3), "2.500000e+03");
}

TEST_F(HopsanCli, AnUnknownParameterNameIsReportedAndTheRunGoesOn)
{
    std::ofstream(mDir / "import.csv") << "# a comment\n"
                                          "ForceSource1#NoSuchParameter,3\n"
                                          "NoSuchComponent#x,1\n"
                                          "Servo9$Gain#k,1\n"
                                          "just one field\n"
                                          "self#Force,1500\n";
    const CliResult r = hopsancli({"-m", kSubSystemModel, "-s", "hmf", "--parameterImport",
                                   (mDir / "import.csv").string(), "--resultsFinalCSV", (mDir / "final.csv").string()});
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("Error: Setting parameter: NoSuchParameter in component: ForceSource1\n"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("Error: No component: NoSuchComponent in system: Sub_System_Example\n"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("Error: Subsystem: Servo9 could not be found in parent system: Sub_System_Example\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("Warning: Wrong line format: just one field\n"), std::string::npos) << r.out;
    // The lines after them still apply, and the run goes to its end.
    EXPECT_EQ(lineNamed(readLines(mDir / "final.csv"), "ForceSource1#P1#Force")->at(3), "1.500000e+03");
    EXPECT_EQ(lineNamed(readLines(mDir / "final.csv"), "Time")->at(3), "1.000000e+01");
}

TEST_F(HopsanCli, ValidateExitsZeroWhenAnHvcPassesAndOneWhenItFails)
{
    const CliResult pass = hopsancli({"-t", kBouncingBallHvc});
    EXPECT_EQ(pass.exitCode, 0) << pass.out;
    EXPECT_NE(pass.out.find("Test successful: Position_Transducer#out#Value"), std::string::npos) << pass.out;
    const CliResult longForm = hopsancli({"--validate", kBouncingBallHvc, "--silent"});
    EXPECT_EQ(longForm.exitCode, 0);
    EXPECT_EQ(longForm.out, "");

    // The same set with a tolerance no engine meets: HopsanCLI's failure line, exit 1.
    std::string strict = readText(kBouncingBallHvc);
    const fs::path validations = fs::path(kBouncingBallHvc).parent_path();
    auto replace = [&](const std::string& from, const std::string& to) {
        const std::size_t at = strict.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        strict.replace(at, from.size(), to);
    };
    replace("../Example Models/Bouncing Ball.hmf",
            fs::relative(validations / "../Example Models/Bouncing Ball.hmf", mDir).string());
    replace(">Bouncing Ball.hvd<", ">" + fs::relative(validations / "Bouncing Ball.hvd", mDir).string() + "<");
    replace("0.010000", "0.0000001");
    std::ofstream(mDir / "strict.hvc") << strict;
    const CliResult fail = hopsancli({"-t", (mDir / "strict.hvc").string()});
    EXPECT_EQ(fail.exitCode, 1) << fail.out;
    EXPECT_NE(fail.out.find("Validation data test failed: Position_Transducer#out#Value"), std::string::npos)
        << fail.out;

    const CliResult missing = hopsancli({"-t", (mDir / "none.hvc").string()});
    EXPECT_EQ(missing.exitCode, 1) << missing.out;
    EXPECT_NE(missing.out.find("Error: "), std::string::npos) << missing.out;
}

TEST_F(HopsanCli, BadArgumentsGiveHopsanCliExitCodes)
{
    const CliResult unknown = hopsancli({"-m", kSubSystemModel, "--noSuchOption"});
    EXPECT_EQ(unknown.exitCode, 1);
    EXPECT_NE(unknown.err.find("PARSE ERROR: Argument: --noSuchOption"), std::string::npos) << unknown.err;
    const CliResult noValue = hopsancli({"-m"});
    EXPECT_EQ(noValue.exitCode, 1);
    EXPECT_NE(noValue.err.find("Missing a value for this argument!"), std::string::npos) << noValue.err;
    const CliResult twice = hopsancli({"-s", "1", "--simulate", "2"});
    EXPECT_EQ(twice.exitCode, 1);
    EXPECT_NE(twice.err.find("Argument already set!"), std::string::npos) << twice.err;
    // Nothing to do is no success either.
    EXPECT_EQ(hopsancli({}).exitCode, 1);
    const CliResult help = hopsancli({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    for (const char* option : {"--hmf", "--simulate", "--numLogSamples", "--parallel", "--parameterImport",
                               "--parameterExport", "--resultsFullCSV", "--resultsFinalCSV", "--resultsCSVSort",
                               "--validate", "--logonly", "--prefixRootSystemName", "--silent", "--externalLib"})
        EXPECT_NE(help.out.find(option), std::string::npos) << option;
    // A model that does not load, a negative thread count (HopsanCLI returns -1), an option
    // HopsanCLI has and hopsancli does not.
    EXPECT_EQ(hopsancli({"-m", (mDir / "none.hmf").string(), "-s", "hmf"}).exitCode, 1);
    EXPECT_EQ(hopsancli({"-m", kSubSystemModel, "-s", "1", "-p", "-1"}).exitCode, 255);
    const CliResult hdf5 = hopsancli({"-m", kSubSystemModel, "-s", "1", "--resultsFullHDF5", "x.h5"});
    EXPECT_EQ(hdf5.exitCode, 1);
    EXPECT_NE(hdf5.out.find("Error: --resultsFullHDF5"), std::string::npos) << hdf5.out;
}

TEST_F(HopsanCli, ExternalLibrariesAreAcceptedWithANote)
{
    const CliResult r = hopsancli({"-e", "libmine.so", "--externalLib", "libother.so", "-m", kSubSystemModel, "-s", "1"});
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("libmine.so: tlmhub's built-in component library is used"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("libother.so"), std::string::npos) << r.out;
}

TEST_F(HopsanCli, ParallelRunsGiveTheSameResults)
{
    const std::string one = (mDir / "one.csv").string(), two = (mDir / "two.csv").string();
    ASSERT_EQ(hopsancli({"-m", kSubSystemModel, "-s", "2", "--resultsFullCSV", one}).exitCode, 0);
    ASSERT_EQ(hopsancli({"-m", kSubSystemModel, "-s", "2", "-p", "2", "--resultsFullCSV", two}).exitCode, 0);
    EXPECT_EQ(readText(two), readText(one));
    ASSERT_EQ(hopsancli({"-m", kSubSystemModel, "-s", "2", "--parallel", "0", "--resultsFullCSV", two}).exitCode, 0);
    EXPECT_EQ(readText(two), readText(one));
}

TEST_F(HopsanCli, LogOnlyKeepsTheNamedPortsAndVariables)
{
    const std::vector<Line> rows =
        fullRows({"-s", "1", "--logonly", "Servo1$Gain#out,ForceSource1#P1#Force,Pulse#nope"}, "only.csv");
    std::vector<std::string> names;
    for (const Line& line : rows) names.push_back(line[0]);
    EXPECT_EQ(names, (std::vector<std::string>{"ForceSource1#P1#Force", "Servo1$Gain#out#Value", "Servo1$Time", "Time"}));

    std::ofstream(mDir / "names.txt") << "Servo2$Cylinder_C#P3#Force\n";
    const CliResult r = hopsancli({"-m", kSubSystemModel, "-s", "1", "--logonly", (mDir / "names.txt").string(),
                                   "--resultsFinalCSV", (mDir / "final.csv").string()});
    EXPECT_EQ(r.exitCode, 0);
    const std::vector<Line> final = readLines(mDir / "final.csv");
    ASSERT_EQ(final.size(), 2u);
    EXPECT_EQ(final[0][0], "Servo2$Cylinder_C#P3#Force");
    EXPECT_EQ(final[1][0], "Servo2$Time");
}

TEST_F(HopsanCli, DestinationAndPrefixApplyToTheExportedFiles)
{
    const CliResult r = hopsancli({"-m", kSubSystemModel, "-s", "1", "-d", mDir.string(), "--prefixRootSystemName",
                                   "--parameterExport", "p.csv", "--resultsFinalCSV", "final.csv", "--silent"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(readText(mDir / "p.csv").rfind("Sub_System_Example$#Force,1000\n", 0), 0u);
    EXPECT_NE(readText(mDir / "p.csv").find("\nSub_System_Example$Servo1$#PGain,0.003\n"), std::string::npos);
    // As HopsanCLI 2.x: the result names keep no root prefix.
    EXPECT_NE(lineNamed(readLines(mDir / "final.csv"), "ForceSource1#P1#Force"), nullptr);
}

} // namespace
} // namespace tlmhub::test
