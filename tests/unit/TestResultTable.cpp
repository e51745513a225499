// ResultTable: the one writer of logged results (CLI --csv, server job results).
#include "TestHelpers.h"

#include "core/ResultTable.h"
#include "core/Results.h"
#include "core/hmf/HmfLoader.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <sstream>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

// The model run to its stop time; the Simulation owns it.
std::optional<Simulation> runModel(const std::string& path)
{
    LoadedModel m = loadHmfFile(path);
    EXPECT_FALSE(m.hasErrors()) << m.firstError();
    if (m.hasErrors()) return std::nullopt;
    return runToStop(compile(std::move(m.root)));
}

// The CSV exactly as tlmhub-cli wrote it before ResultTable existed (printf per cell).
std::string referenceCsv(const System& root)
{
    std::string out = "time";
    const auto vars = listLoggedVariables(root);
    std::vector<std::vector<double>> columns;
    for (const auto& v : vars) {
        out += "," + v.fullName;
        columns.push_back(loggedData(*v.port, v.slot, v.count));
    }
    out += "\n";
    char buf[64];
    for (std::size_t r = 0; r < root.numLoggedSamples(); ++r) {
        std::snprintf(buf, sizeof buf, "%.17g", root.logTime()[r]);
        out += buf;
        for (const auto& col : columns) {
            if (r < col.size()) {
                std::snprintf(buf, sizeof buf, ",%.17g", col[r]);
                out += buf;
            } else {
                out += ",";
            }
        }
        out += "\n";
    }
    return out;
}

std::vector<std::vector<std::string>> parseCsv(const std::string& csv)
{
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(csv);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream ls(line);
        while (std::getline(ls, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.push_back("");
        rows.push_back(cells);
    }
    return rows;
}

bool bitwiseEqual(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

ResultTable smallTable()
{
    ResultTable t;
    t.time = {0.0, 0.5, 1.0};
    t.columns.push_back({"A#P1#Pressure", "Pa", {1e5, 1.0 / 3.0, -2.5e-300}});
    t.columns.push_back({"B#out#Value", "", {std::numeric_limits<double>::quiet_NaN(), 7.0}});
    t.columns.push_back({"Sub$C#P2#Flow", "m^3/s", {0.1, 0.2, 0.3}});
    return t;
}

} // namespace

TEST(ResultTable, FromViewHasEveryLoggedVariableInListOrder)
{
    auto sim = runModel(std::string(TLMHUB_SOURCE_DIR) + "/examples/pressure-build-up.hmf");
    ASSERT_TRUE(sim);
    const ResultTable t = ResultTable::fromView(sim->results());
    const auto vars = listLoggedVariables(sim->system());
    ASSERT_EQ(t.columns.size(), vars.size());
    ASSERT_GT(vars.size(), 0u);
    EXPECT_EQ(t.time.size(), sim->system().numLoggedSamples());
    EXPECT_EQ(t.time.size(), 501u);
    for (std::size_t i = 0; i < vars.size(); ++i) {
        EXPECT_EQ(t.columns[i].name, vars[i].fullName);
        EXPECT_EQ(t.columns[i].unit, vars[i].unit);
        EXPECT_TRUE(bitwiseEqual(t.columns[i].data, loggedData(*vars[i].port, vars[i].slot, vars[i].count)))
            << vars[i].fullName;
    }
}

TEST(ResultTable, CsvIsByteIdenticalToThePrintfFormat)
{
    auto sim = runModel(std::string(TLMHUB_SOURCE_DIR) + "/examples/pressure-build-up.hmf");
    ASSERT_TRUE(sim);
    EXPECT_EQ(ResultTable::fromView(sim->results()).toCsv(), referenceCsv(sim->system()));
}

TEST(ResultTable, CsvOfModelWithSubsystemsIsByteIdentical)
{
    const std::string path = sharedDir() + "/hopsan-models/Example Models/Sub System Example.hmf";
    ASSERT_TRUE(std::filesystem::exists(path)) << "shared model missing: " << path;
    auto sim = runModel(path);
    ASSERT_TRUE(sim);
    const ResultTable t = ResultTable::fromView(sim->results());
    bool nested = false;
    for (const auto& c : t.columns) nested = nested || c.name.find('$') != std::string::npos;
    EXPECT_TRUE(nested);
    EXPECT_EQ(t.toCsv(), referenceCsv(sim->system()));
}

TEST(ResultTable, CsvValuesReadBackExactly)
{
    auto sim = runModel(std::string(TLMHUB_SOURCE_DIR) + "/examples/pressure-build-up.hmf");
    ASSERT_TRUE(sim);
    const ResultTable t = ResultTable::fromView(sim->results());
    const auto rows = parseCsv(t.toCsv());
    ASSERT_EQ(rows.size(), t.time.size() + 1);
    ASSERT_EQ(rows[0].size(), t.columns.size() + 1);
    EXPECT_EQ(rows[0][0], "time");
    for (std::size_t c = 0; c < t.columns.size(); ++c) EXPECT_EQ(rows[0][c + 1], t.columns[c].name);
    for (std::size_t r = 0; r < t.time.size(); ++r) {
        ASSERT_EQ(rows[r + 1].size(), t.columns.size() + 1);
        EXPECT_EQ(std::strtod(rows[r + 1][0].c_str(), nullptr), t.time[r]);
        for (std::size_t c = 0; c < t.columns.size(); ++c)
            ASSERT_EQ(std::strtod(rows[r + 1][c + 1].c_str(), nullptr), t.columns[c].data[r])
                << t.columns[c].name << " row " << r;
    }
}

TEST(ResultTable, ShorterColumnLeavesEmptyCells)
{
    const std::string csv = smallTable().toCsv();
    EXPECT_EQ(csv,
              "time,A#P1#Pressure,B#out#Value,Sub$C#P2#Flow\n"
              "0,100000,nan,0.10000000000000001\n"
              "0.5,0.33333333333333331,7,0.20000000000000001\n"
              "1,-2.5e-300,,0.29999999999999999\n");
}

TEST(ResultTable, VariableFilterPicksAndOrdersColumns)
{
    const ResultTable t = smallTable();
    EXPECT_EQ(t.toCsv({"Sub$C#P2#Flow", "nope", "A#P1#Pressure"}),
              "time,Sub$C#P2#Flow,A#P1#Pressure\n"
              "0,0.10000000000000001,100000\n"
              "0.5,0.20000000000000001,0.33333333333333331\n"
              "1,0.29999999999999999,-2.5e-300\n");
    const nlohmann::json j = t.toJson({"B#out#Value"});
    ASSERT_EQ(j.at("variables").size(), 1u);
    EXPECT_EQ(j.at("variables")[0].at("name"), "B#out#Value");
    EXPECT_EQ(j.at("variables")[0].at("unit"), "");
    EXPECT_EQ(j.at("variables")[0].at("data").size(), 2u);
    EXPECT_EQ(j.at("time"), nlohmann::json({0.0, 0.5, 1.0}));
    EXPECT_EQ(t.toJson().at("variables").size(), 3u);
    EXPECT_TRUE(t.hasColumn("A#P1#Pressure"));
    EXPECT_FALSE(t.hasColumn("A#P1#Flow"));
}

TEST(ResultTable, SerializeRoundTripsBitwise)
{
    const ResultTable t = smallTable();
    const std::string bytes = t.serialize();
    EXPECT_EQ(bytes.size(), t.byteSize());
    ResultTable back;
    ASSERT_TRUE(ResultTable::deserialize(bytes, back));
    EXPECT_TRUE(bitwiseEqual(back.time, t.time));
    ASSERT_EQ(back.columns.size(), t.columns.size());
    for (std::size_t i = 0; i < t.columns.size(); ++i) {
        EXPECT_EQ(back.columns[i].name, t.columns[i].name);
        EXPECT_EQ(back.columns[i].unit, t.columns[i].unit);
        EXPECT_TRUE(bitwiseEqual(back.columns[i].data, t.columns[i].data));
    }
    EXPECT_EQ(back.toCsv(), t.toCsv());
}

TEST(ResultTable, SerializedDoublesAreLittleEndian)
{
    ResultTable t;
    t.time = {1.0};   // 0x3FF0000000000000
    const std::string bytes = t.serialize();
    // magic(4) version(4) count(8), then the double's bytes, lowest first.
    ASSERT_GE(bytes.size(), 24u);
    EXPECT_EQ(bytes.substr(0, 4), "TLRT");
    EXPECT_EQ(static_cast<unsigned char>(bytes[8]), 1u);
    EXPECT_EQ(static_cast<unsigned char>(bytes[16]), 0x00u);
    EXPECT_EQ(static_cast<unsigned char>(bytes[22]), 0xF0u);
    EXPECT_EQ(static_cast<unsigned char>(bytes[23]), 0x3Fu);
}

TEST(ResultTable, DeserializeRefusesDamagedInput)
{
    const std::string bytes = smallTable().serialize();
    ResultTable out;
    out.time = {42.0};
    EXPECT_FALSE(ResultTable::deserialize(bytes.substr(0, bytes.size() - 1), out));
    EXPECT_FALSE(ResultTable::deserialize(bytes + "x", out));
    EXPECT_FALSE(ResultTable::deserialize("XXXX" + bytes.substr(4), out));
    EXPECT_FALSE(ResultTable::deserialize("", out));
    EXPECT_EQ(out.time, std::vector<double>{42.0});   // unchanged on failure
}

TEST(ResultTable, NumbersFormatExactlyAsPrintf)
{
    // Random bit patterns cover subnormals, infinities, NaNs and every exponent.
    std::mt19937_64 rng(12345);
    ResultTable t;
    ResultColumn c{"x", "", {}};
    for (int i = 0; i < 100000; ++i) {
        t.time.push_back(static_cast<double>(i));
        c.data.push_back(std::bit_cast<double>(rng()));
    }
    t.columns.push_back(c);
    std::string expected = "time,x\n";
    char buf[64];
    for (std::size_t i = 0; i < t.time.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.17g,%.17g\n", t.time[i], c.data[i]);
        expected += buf;
    }
    EXPECT_EQ(t.toCsv(), expected);
}
